// Shared by the viewer tests: start `pgamesh serve` on a free loopback port, read meshes
// independently of the server, raw HTTP for requests that fetch() would normalise.
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import net from 'node:net';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

export const repoRoot = resolve(dirname(fileURLToPath(import.meta.url)), '..', '..');
// PGAMESH_CLI: the pgamesh to test — scripts/test.sh gives the installed one.
export const cliPath = process.env.PGAMESH_CLI || join(repoRoot, 'build', 'release', 'pgamesh');
export const tankPath = join(repoRoot, 'data', 'meshes', 'tank.obj');
export const artifactsDir = join(repoRoot, 'test-artifacts', 'viewer');

// Servers still running when the test process ends (a failed test) are killed with it.
const running = new Set();
process.on('exit', () => { for (const child of running) child.kill('SIGKILL'); });

// Starts the server with extra arguments; resolves to { url, child, stderr(), exited, stop() }
// once it printed its URL. Rejects when it exits first or prints no URL within 10 s.
export function startServer(args = []) {
  return new Promise((resolvePromise, reject) => {
    // PGAMESH_SERVE_CWD: start it elsewhere than the clone (the installed server must find its
    // page relative to its executable, not the working directory).
    const child = spawn(cliPath, ['serve', '--port', '0', ...args],
                        { stdio: ['ignore', 'pipe', 'pipe'],
                          cwd: process.env.PGAMESH_SERVE_CWD || undefined });
    running.add(child);
    child.once('exit', () => running.delete(child));
    let out = '', err = '';
    const exited = new Promise((r) => child.once('exit', (code, signal) => r({ code, signal })));
    const timer = setTimeout(() => {
      child.kill('SIGKILL');
      reject(new Error(`pgamesh serve printed no URL within 10 s; stderr: ${err}`));
    }, 10000);
    child.stderr.on('data', (d) => { err += d; });
    child.stdout.on('data', (d) => {
      out += d;
      const m = /listening on (http:\/\/\S+)/.exec(out);
      if (m) {
        clearTimeout(timer);
        resolvePromise({
          url: m[1],
          child,
          stderr: () => err,
          exited,
          // SIGTERM, then SIGKILL after 5 s; resolves to { code, signal } ({ signal:
          // 'SIGKILL' } tells that the server did not stop by itself).
          stop: async () => {
            if (child.exitCode === null && child.signalCode === null) child.kill('SIGTERM');
            const timer = setTimeout(() => child.kill('SIGKILL'), 5000);
            const result = await exited;
            clearTimeout(timer);
            return result;
          },
        });
      }
    });
    exited.then(({ code }) => {
      clearTimeout(timer);
      reject(new Error(`pgamesh serve exited with ${code} before listening; stderr: ${err}`));
    });
  });
}

// Runs the CLI to completion: { code, stdout, stderr }.
export function runCli(args, timeoutMs = 20000) {
  return new Promise((resolvePromise) => {
    const child = spawn(cliPath, args, { stdio: ['ignore', 'pipe', 'pipe'] });
    let stdout = '', stderr = '';
    child.stdout.on('data', (d) => { stdout += d; });
    child.stderr.on('data', (d) => { stderr += d; });
    const timer = setTimeout(() => child.kill('SIGKILL'), timeoutMs);
    child.on('exit', (code) => {
      clearTimeout(timer);
      resolvePromise({ code, stdout, stderr });
    });
  });
}

// Sends one raw HTTP/1.1 request (request line written exactly as given, Host as a browser sends
// it unless given) and resolves to { status, headers, body } of the answer.
export function rawRequest(url, requestLine, extraHeaders = '', host = new URL(url).host) {
  const { hostname, port } = new URL(url);
  return new Promise((resolvePromise, reject) => {
    const socket = net.connect(Number(port), hostname, () => {
      socket.write(`${requestLine}\r\nHost: ${host}\r\nConnection: close\r\n${extraHeaders}\r\n`);
    });
    let data = '';
    let done = false;
    // Answers are complete at Content-Length: a server may keep the connection open after a
    // request it could not parse (it never saw "Connection: close").
    const finish = () => {
      const end = data.indexOf('\r\n\r\n');
      if (done || end < 0) return;
      const { status, headers } = parseHead(data.slice(0, end));
      const body = data.slice(end + 4);
      if (body.length < Number(headers['content-length'] || 0)) return;
      done = true;
      socket.destroy();
      resolvePromise({ status, headers, body });
    };
    socket.setTimeout(5000, () => socket.destroy(new Error('raw request timed out')));
    socket.on('data', (d) => {
      data += d.toString('latin1');
      finish();
    });
    socket.on('error', (e) => { if (!done) reject(e); });
    socket.on('end', () => {
      finish();
      if (!done) reject(new Error(`incomplete answer: ${JSON.stringify(data)}`));
    });
  });
}

// Writes `prefix` at once, then `text` one byte every `byteMs` ms, as a slow client does. Resolves
// to { closedAfterMs, sent, answer }: when the server ended the connection (null if it had not
// within `giveUpMs`), how many bytes of `text` had gone, and what it answered (if anything).
export function trickle(url, text, byteMs, giveUpMs, { prefix = '' } = {}) {
  const { hostname, port } = new URL(url);
  return new Promise((resolvePromise) => {
    const start = Date.now();
    let sent = 0, answer = '', timer = null, done = false;
    const socket = net.connect(Number(port), hostname);
    const finish = (closed) => {
      if (done) return;
      done = true;
      clearTimeout(timer);
      socket.destroy();
      resolvePromise({ closedAfterMs: closed ? Date.now() - start : null, sent, answer });
    };
    const writeNext = () => {
      if (done) return;
      if (Date.now() - start > giveUpMs) return finish(false);
      if (sent < text.length) socket.write(text[sent++]);
      timer = setTimeout(writeNext, byteMs);
    };
    socket.on('connect', () => {
      socket.write(prefix);
      writeNext();
    });
    socket.on('data', (d) => { answer += d.toString('latin1'); });
    socket.on('end', () => finish(true));
    socket.on('close', () => finish(true));
    socket.on('error', () => finish(true));
  });
}

// Parses the head of an HTTP answer: { status, headers } (header names in lower case).
function parseHead(head) {
  const lines = head.split('\r\n');
  const headers = {};
  for (const l of lines.slice(1)) {
    const i = l.indexOf(':');
    headers[l.slice(0, i).trim().toLowerCase()] = l.slice(i + 1).trim();
  }
  return { status: Number(lines[0].split(' ')[1]), headers };
}

// POSTs a chunked body of `chunks` chunks of `chunkSize` bytes of OBJ comment text to `path`, one
// chunk per event-loop turn, stopping when the server answers. With `finish: false` the body is
// left unfinished (no last chunk): only a server that stops reading at its limit can answer it.
// Resolves to { status, headers, body, closed }: `closed` whether the server closed the
// connection within 1 s of its answer.
export function sendChunked(url, path, chunks, chunkSize, { finish = true } = {}) {
  const { hostname, port, host } = new URL(url);
  return new Promise((resolvePromise, reject) => {
    const socket = net.connect(Number(port), hostname);
    let data = '', answer = null, closed = false;
    const chunk = `${chunkSize.toString(16)}\r\n${'#'.repeat(chunkSize - 1)}\n\r\n`;
    const writeMore = (i) => {
      if (answer || socket.destroyed) return;
      if (i < chunks) socket.write(chunk, () => setImmediate(() => writeMore(i + 1)));
      else if (finish) socket.write('0\r\n\r\n');
    };
    const settle = () => {
      socket.destroy();
      if (answer) resolvePromise({ ...answer, closed });
      else reject(new Error(`no answer to the chunked upload: ${JSON.stringify(data)}`));
    };
    socket.on('connect', () => {
      socket.write(`POST ${path} HTTP/1.1\r\nHost: ${host}\r\n` +
                   'Content-Type: application/octet-stream\r\nTransfer-Encoding: chunked\r\n\r\n');
      writeMore(0);
    });
    socket.setTimeout(10000, settle);
    socket.on('data', (d) => {
      data += d.toString('latin1');
      const end = data.indexOf('\r\n\r\n');
      if (answer || end < 0) return;
      const { status, headers } = parseHead(data.slice(0, end));
      const body = data.slice(end + 4);
      if (body.length < Number(headers['content-length'] || 0)) return;
      answer = { status, headers, body };
      setTimeout(settle, 1000);
    });
    // The server may reset the connection while chunks are still in flight: the answer read
    // before counts.
    socket.on('error', () => {});
    socket.on('close', () => {
      closed = true;
      settle();
    });
  });
}

// An OBJ read here, independently of the library: vertices [[x,y,z]], faces [[i,j,k,...]]
// (0-based; positive indices only, which is what the test meshes use).
export function readObj(path) {
  const vertices = [], faces = [];
  for (const line of readFileSync(path, 'utf8').split('\n')) {
    const t = line.trim().split(/\s+/);
    if (t[0] === 'v') vertices.push(t.slice(1, 4).map(Number));
    if (t[0] === 'f') faces.push(t.slice(1).map((s) => Number(s.split('/')[0]) - 1));
  }
  return { vertices, faces };
}

// Bounds of an OBJ read by readObj.
export function objBounds({ vertices }) {
  const min = [Infinity, Infinity, Infinity], max = [-Infinity, -Infinity, -Infinity];
  for (const v of vertices)
    for (let k = 0; k < 3; ++k) {
      min[k] = Math.min(min[k], v[k]);
      max[k] = Math.max(max[k], v[k]);
    }
  return { min, max };
}

// A unit right tetrahedron as OBJ text (outward counter-clockwise faces).
export const tetrahedronObj = [
  'v 0 0 0', 'v 1 0 0', 'v 0 1 0', 'v 0 0 1',
  'f 1 3 2', 'f 1 2 4', 'f 1 4 3', 'f 2 3 4', '',
].join('\n');

// Mass properties of a closed polyhedron by the classical divergence-theorem sums over the
// tetrahedra (origin, a, b, c) of its fan-triangulated faces: an independent reference for the
// library's PGA path. ∫ x xᵀ dV over a tetrahedron with vertices 0, a, b, c is
// det/120 · (a aᵀ + b bᵀ + c cᵀ + s sᵀ), s = a + b + c.
export function referenceProps({ vertices, faces }, density = 1) {
  let volume = 0, area = 0;
  const first = [0, 0, 0];
  const second = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
  const sub = (p, q) => [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
  const cross = (p, q) => [p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2],
                           p[0] * q[1] - p[1] * q[0]];
  const dot = (p, q) => p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
  for (const f of faces)
    for (let k = 1; k + 1 < f.length; ++k) {
      const a = vertices[f[0]], b = vertices[f[k]], c = vertices[f[k + 1]];
      const det = dot(a, cross(b, c));
      area += Math.hypot(...cross(sub(b, a), sub(c, a))) / 2;
      volume += det / 6;
      const s = [a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]];
      for (let i = 0; i < 3; ++i) {
        first[i] += (det / 24) * s[i];
        for (let j = 0; j < 3; ++j)
          second[i][j] += (det / 120) * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
      }
    }
  const com = first.map((x) => x / volume);
  // Inertia about the centre of mass: ρ (tr(C) 1 − C) with C = ∫ r rᵀ dV − V c cᵀ.
  const central = second.map((row, i) => row.map((x, j) => x - volume * com[i] * com[j]));
  const trace = central[0][0] + central[1][1] + central[2][2];
  const inertia = central.map((row, i) => row.map((x, j) => density * ((i === j ? trace : 0) - x)));
  return { volume, area, mass: density * volume, center_of_mass: com, inertia_com: inertia };
}

// |a − b| ≤ tol · scale for numbers, or element-wise for nested arrays.
export function near(actual, expected, scale, tol = 1e-9) {
  if (Array.isArray(expected)) return expected.every((e, i) => near(actual[i], e, scale, tol));
  return Math.abs(actual - expected) <= tol * scale;
}
