// The server under load, on loopback: many concurrent keep-alive connections mixing the page,
// figures, the mesh list and fuel queries; parallel 10 MB binary STL uploads; slow clients that
// trickle their request heads byte by byte. Every legitimate request must be answered 2xx, the
// server must stay up, and its peak resident memory (VmHWM) must stay bounded.
//
// Bounded and self-stopping: counts scale with PGAMESH_LOAD_SCALE (default 1, ~15 s on two
// cores; 10 gives the figures in docs/viewer.md "Under load"), every request has a timeout.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import http from 'node:http';
import net from 'node:net';
import { after, before, test } from 'node:test';

import { startServer } from './support.mjs';

const scale = Math.max(0.1, Number(process.env.PGAMESH_LOAD_SCALE || 1));
const counts = {
  connections: Math.max(4, Math.round(20 * scale)),  // concurrent keep-alive connections
  requests: Math.max(100, Math.round(2000 * scale)),  // GETs in the mixed phase
  uploads: Math.max(1, Math.round(5 * scale)),  // parallel 10 MB uploads, during the mixed phase
  // Slow clients, with figures requests beside them: at least 50 at every scale, more than the
  // 32 workers, and connecting at once (a burst once overflowed httplib's accept backlog of 5).
  slow: Math.max(50, Math.round(5 * scale)),
};
// Slow clients write one byte of their request head every `slowByteMs`, so each one holds a
// server worker for about head length × slowByteMs (~3.6 s), within the 5 s read timeout per byte.
const slowByteMs = 40;
const requestTimeoutMs = 60000;
// Peak RSS bound: the server keeps at most 8 uploads, but up to 32 workers (one per connection)
// may each hold a 10 MB body being read (std::string growth: up to 2x), the parsed mesh and its
// summary at once; 32 x ~40 MB plus the bundled meshes and fuel indexes stays well under 1.5 GB.
// A leak or an unbounded queue of bodies (50 x 10 MB x copies) would cross it at full scale.
const rssLimitBytes = 1.5 * 1024 ** 3;

let server;
before(async () => { server = await startServer(['--quiet']); });
after(async () => { await server.stop(); });

// A binary STL of about `bytes` bytes: a height-field grid of triangles (shared corners, as a
// real part has), 84-byte header + 50 bytes per triangle.
function binaryStl(bytes) {
  const side = Math.floor(Math.sqrt((bytes - 84) / 100));
  const triangles = 2 * side * side;
  const buf = Buffer.alloc(84 + 50 * triangles);
  buf.write('pgamesh load test', 0, 'latin1');
  buf.writeUInt32LE(triangles, 80);
  const z = (i, j) => 0.1 * Math.sin(i / 7) * Math.cos(j / 11);
  let o = 84;
  const put = (tri) => {
    o += 12;  // normal left zero: readers recompute it
    for (const p of tri) for (const c of p) { buf.writeFloatLE(c, o); o += 4; }
    o += 2;
  };
  for (let i = 0; i < side; ++i)
    for (let j = 0; j < side; ++j) {
      const a = [i, j, z(i, j)], b = [i + 1, j, z(i + 1, j)];
      const c = [i + 1, j + 1, z(i + 1, j + 1)], d = [i, j + 1, z(i, j + 1)];
      put([a, b, c]);
      put([a, c, d]);
    }
  return { buf, triangles };
}

// One request through `agent`; resolves to { status, ms, bytes } or { error, ms }.
function request(agent, method, path, body) {
  const { hostname, port } = new URL(server.url);
  const start = process.hrtime.bigint();
  const ms = () => Number(process.hrtime.bigint() - start) / 1e6;
  return new Promise((resolve) => {
    const req = http.request({ hostname, port, path, method, agent, timeout: requestTimeoutMs,
                               headers: body ? { 'Content-Type': 'application/octet-stream',
                                                 'Content-Length': body.length } : {} },
                             (res) => {
      let bytes = 0;
      res.on('data', (d) => { bytes += d.length; });
      res.on('end', () => resolve({ status: res.statusCode, ms: ms(), bytes }));
      res.on('error', (e) => resolve({ error: e.message, ms: ms() }));
    });
    req.on('timeout', () => req.destroy(new Error('timed out')));
    req.on('error', (e) => resolve({ error: e.message, ms: ms() }));
    req.end(body);
  });
}

// Runs `jobs` (functions returning promises) with at most `width` in flight.
async function pool(jobs, width) {
  const results = new Array(jobs.length);
  let next = 0;
  const worker = async () => {
    while (next < jobs.length) {
      const i = next++;
      results[i] = await jobs[i]();
    }
  };
  await Promise.all(Array.from({ length: Math.min(width, jobs.length) }, worker));
  return results;
}

function percentile(sorted, p) {
  if (sorted.length === 0) return NaN;
  return sorted[Math.min(sorted.length - 1, Math.floor((p / 100) * sorted.length))];
}

// A slow client: connects, writes a legitimate GET head one byte every `slowByteMs`, then
// reads the answer. Resolves to { status, ms } or { error, ms }.
function slowClient(path) {
  const { hostname, port, host } = new URL(server.url);
  const head = `GET ${path} HTTP/1.1\r\nHost: ${host}\r\nConnection: close\r\n\r\n`;
  const start = Date.now();
  return new Promise((resolve) => {
    const socket = net.connect(Number(port), hostname);
    let data = '', i = 0, timer = null, done = false;
    const finish = (r) => {
      if (done) return;
      done = true;
      clearTimeout(timer);
      socket.destroy();
      resolve({ ...r, ms: Date.now() - start });
    };
    const writeNext = () => {
      if (socket.destroyed) return;
      socket.write(head[i++]);
      if (i < head.length) timer = setTimeout(writeNext, slowByteMs);
    };
    socket.on('connect', writeNext);
    socket.setTimeout(requestTimeoutMs, () => finish({ error: 'timed out' }));
    socket.on('data', (d) => { data += d.toString('latin1'); });
    socket.on('error', (e) => finish({ error: e.message }));
    socket.on('close', () => {
      const m = /^HTTP\/1\.1 (\d{3})/.exec(data);
      finish(m ? { status: Number(m[1]), ...(m[1] === '200' ? {} : { answer: data.slice(-200) }) }
               : { error: `no answer: ${JSON.stringify(data)}` });
    });
  });
}

function peakRss(pid) {
  const status = readFileSync(`/proc/${pid}/status`, 'utf8');
  const kb = (name) => Number(new RegExp(`^${name}:\\s+(\\d+) kB`, 'm').exec(status)[1]);
  return { hwm: kb('VmHWM') * 1024, rss: kb('VmRSS') * 1024 };
}

function summarise(label, results) {
  const failed = results.filter((r) => r.error || r.status < 200 || r.status >= 300);
  const ms = results.filter((r) => !r.error).map((r) => r.ms).sort((a, b) => a - b);
  return { label, n: results.length, failed: failed.length,
           p50: percentile(ms, 50), p99: percentile(ms, 99), max: ms.at(-1) ?? NaN,
           examples: failed.slice(0, 3) };
}

test(`under load (scale ${scale}): every legitimate request answered, memory bounded`,
     { timeout: 600000 }, async () => {
  const list = await (await fetch(new URL('/api/meshes', server.url))).json();
  const tank = list.meshes.find((m) => m.name === 'tank.obj');
  assert.ok(tank, 'the bundled tank is listed');
  const figures = '/api/mesh/f1/props?density=800';
  const paths = [
    () => '/',
    () => figures,
    () => '/api/meshes',
    () => `/api/mesh/${tank.id}/fuel?pitch=${(Math.random() * 20 - 10).toFixed(2)}` +
          `&roll=${(Math.random() * 20 - 10).toFixed(2)}&level=${(0.2 + Math.random() * 0.8).toFixed(3)}`,
    () => `/api/mesh/${tank.id}/fuel?pitch=3&roll=-2&volume=${(0.5 + Math.random()).toFixed(3)}`,
  ];
  const { buf: stl, triangles } = binaryStl(10 * 1000 * 1000);
  const started = Date.now();

  // Phase 1: the mixed GETs on `connections` keep-alive connections, the uploads beside them.
  const agent = new http.Agent({ keepAlive: true, maxSockets: counts.connections });
  const uploadAgent = new http.Agent({ keepAlive: false, maxSockets: counts.uploads });
  const kinds = [];
  const gets = Array.from({ length: counts.requests }, (_, i) => {
    const k = i % paths.length;
    kinds.push(k);
    return () => request(agent, 'GET', paths[k]());
  });
  const uploads = Array.from({ length: counts.uploads }, (_, i) =>
    () => request(uploadAgent, 'POST', `/api/upload?name=load-${i}.stl`, stl));
  const [getResults, uploadResults] = await Promise.all([
    pool(gets, counts.connections),
    Promise.all(uploads.map((u) => u())),
  ]);
  agent.destroy();
  uploadAgent.destroy();
  const mixedMs = Date.now() - started;

  // Phase 2: slow clients hold connections (more than the 32 workers at full scale) while
  // figures requests go on beside them on fresh connections.
  const slowStarted = Date.now();
  const slow = Array.from({ length: counts.slow }, () => slowClient(figures));
  const besideAgent = new http.Agent({ keepAlive: false, maxSockets: 4 });
  const beside = [];
  let slowDone = false;
  const slowAll = Promise.all(slow).then((r) => { slowDone = true; return r; });
  const besideLoop = (async () => {
    while (!slowDone) beside.push(await request(besideAgent, 'GET', figures));
  })();
  const [slowResults] = await Promise.all([slowAll, besideLoop]);
  besideAgent.destroy();
  const slowMs = Date.now() - slowStarted;

  const { hwm, rss } = peakRss(server.child.pid);
  const rows = [
    summarise('figures (mixed)', getResults.filter((_, i) => kinds[i] === 1)),
    summarise('page /', getResults.filter((_, i) => kinds[i] === 0)),
    summarise('mesh list', getResults.filter((_, i) => kinds[i] === 2)),
    summarise('fuel', getResults.filter((_, i) => kinds[i] >= 3)),
    summarise('all GETs', getResults),
    summarise('10 MB uploads', uploadResults),
    summarise('slow clients', slowResults),
    summarise('figures beside slow', beside),
  ];
  const f = (x) => (Number.isFinite(x) ? x.toFixed(1) : '-');
  console.log(`load: scale ${scale}, ${counts.connections} connections, ${counts.requests} GETs ` +
              `+ ${counts.uploads} uploads of ${(stl.length / 1e6).toFixed(1)} MB ` +
              `(${triangles} triangles) in ${mixedMs} ms; ${counts.slow} slow clients ` +
              `(${slowByteMs} ms/byte) for ${slowMs} ms`);
  console.log('| requests | n | failed | p50 ms | p99 ms | max ms |');
  console.log('| --- | --- | --- | --- | --- | --- |');
  for (const r of rows)
    console.log(`| ${r.label} | ${r.n} | ${r.failed} | ${f(r.p50)} | ${f(r.p99)} | ${f(r.max)} |`);
  console.log(`server peak RSS (VmHWM) ${(hwm / 2 ** 20).toFixed(0)} MiB, ` +
              `RSS at the end ${(rss / 2 ** 20).toFixed(0)} MiB`);

  for (const r of rows) assert.equal(r.failed, 0, `${r.label}: ${JSON.stringify(r.examples)}`);
  for (const u of uploadResults) assert.equal(u.status, 201);
  assert.ok(beside.length > 0, 'figures requests ran beside the slow clients');
  // Still up and answering after all of it.
  const info = await fetch(new URL('/api/info', server.url));
  assert.equal(info.status, 200);
  assert.equal(server.child.exitCode, null);
  assert.ok(hwm < rssLimitBytes, `peak RSS ${hwm} bytes over ${rssLimitBytes}`);
});
