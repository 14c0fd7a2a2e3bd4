// What the server refuses: bodies over the limit however they are sent, requests for other host
// names (DNS rebinding) and from other sites' pages, addresses other machines reach unless asked
// for, and command lines naming what cannot be served.
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import net from 'node:net';
import { after, before, describe, test } from 'node:test';

import {
  rawRequest, runCli, sendChunked, startServer, tankPath, tetrahedronObj, trickle,
} from './support.mjs';

let server;
before(async () => { server = await startServer(['--quiet']); });
after(async () => { await server.stop(); });

async function serverAnswers(url) {
  const r = await fetch(new URL('/api/info', url));
  assert.equal(r.status, 200);
}

describe('body limits', () => {
  test('a chunked body over the limit gets 413, the connection closed, the server up',
       async () => {
    const small = await startServer(['--max-upload', '1K', '--quiet']);
    try {
      const r = await sendChunked(small.url, '/api/upload?name=long.obj', 2000, 1024);
      assert.equal(r.status, 413);
      assert.match(JSON.parse(r.body).error, /upload limit of 1024 bytes/);
      assert.equal(r.closed, true);
      await serverAnswers(small.url);
    } finally {
      await small.stop();
    }
  });

  test('a declared length over the limit: 413 read in full, or before sending when asked',
       async () => {
    const small = await startServer(['--max-upload', '1K', '--quiet']);
    try {
      const big = `# ${'x'.repeat(2 << 20)}\n${tetrahedronObj}`;
      for (let i = 0; i < 3; ++i) {
        const r = await fetch(new URL('/api/upload?name=big.obj', small.url),
                              { method: 'POST', body: big });
        assert.equal(r.status, 413);
        assert.match((await r.json()).error, /upload limit of 1024 bytes/);
      }
      const asked = await rawRequest(small.url, 'POST /api/upload?name=big.obj HTTP/1.1',
                                     'Content-Length: 2048\r\nExpect: 100-continue\r\n');
      assert.equal(asked.status, 413);
      assert.match(JSON.parse(asked.body).error, /upload limit of 1024 bytes/);
      await serverAnswers(small.url);
    } finally {
      await small.stop();
    }
  });

  test('100 MB chunked to the default 64M limit: 413, and the server still answers', async () => {
    const r = await sendChunked(server.url, '/api/upload?name=huge.stl', 1600, 64 * 1024);
    assert.equal(r.status, 413);
    assert.match(JSON.parse(r.body).error, /upload limit of 67108864 bytes/);
    assert.equal(r.closed, true);
    await serverAnswers(server.url);
  });

  test('a chunked body under the limit reaches the reader', async () => {
    const chunked = await sendChunked(server.url, '/api/upload?name=padding.obj', 4, 1024);
    // Comment lines only: a readable OBJ without faces, refused by the reader, not the limit.
    assert.equal(chunked.status, 400);
    assert.doesNotMatch(JSON.parse(chunked.body).error, /limit/);
  });

  test('a Content-Length over the limit is refused before the body is read', async () => {
    const r = await rawRequest(server.url, 'POST /api/upload?name=huge.obj HTTP/1.1',
                               'Content-Length: 1000000000000\r\n');
    assert.equal(r.status, 413);
    assert.equal(r.headers.connection, 'close');
    await serverAnswers(server.url);
  });

  test('a form-urlencoded body of 100 KB is an upload like any other', async () => {
    const padded = `# ${'x'.repeat(100 * 1024)}\n${tetrahedronObj}`;
    const r = await fetch(new URL('/api/upload?name=form.obj', server.url), {
      method: 'POST', body: padded,
      headers: { 'content-type': 'application/x-www-form-urlencoded' },
    });
    assert.equal(r.status, 201);
    assert.equal((await r.json()).faces, 4);
  });

  test('a body on a route that takes none is refused and the connection closed', async () => {
    const r = await rawRequest(server.url, 'GET /api/info HTTP/1.1',
                               'Transfer-Encoding: chunked\r\n');
    assert.equal(r.status, 413);
    assert.equal(r.headers.connection, 'close');
  });
});

describe('requests that never end', { concurrency: true }, () => {
  // Each byte comes well within the 5 s per-read timeout: only a whole-request deadline ends these.
  test('a request head trickled past --head-timeout is cut; other requests are answered meanwhile',
       async () => {
    const strict = await startServer(['--quiet', '--head-timeout', '1', '--request-timeout', '2']);
    try {
      const host = new URL(strict.url).host;
      const head = `GET /api/info HTTP/1.1\r\nHost: ${host}\r\nX-Pad: ${'a'.repeat(200)}\r\n\r\n`;
      const [slow] = await Promise.all([trickle(strict.url, head, 50, 8000),
                                        serverAnswers(strict.url)]);
      assert.notEqual(slow.closedAfterMs, null, 'the slow head was never cut');
      assert.ok(slow.closedAfterMs >= 1000 && slow.closedAfterMs < 3000, `${slow.closedAfterMs} ms`);
      assert.ok(slow.sent < head.length, 'the head was sent whole before the cut');
      assert.equal(slow.answer, '');
      await serverAnswers(strict.url);
    } finally {
      await strict.stop();
    }
  });

  test('a body trickled past --request-timeout is cut; a prompt one on the same terms is not',
       async () => {
    const strict = await startServer(['--quiet', '--head-timeout', '1', '--request-timeout', '1']);
    try {
      const host = new URL(strict.url).host;
      const body = tetrahedronObj;
      const request = `POST /api/upload?name=t.obj HTTP/1.1\r\nHost: ${host}\r\n` +
                      `Content-Length: ${body.length}\r\n\r\n`;
      // The head at once, then the body a byte every 50 ms (about 3 s in all).
      const slow = await trickle(strict.url, body, 50, 8000, { prefix: request });
      assert.notEqual(slow.closedAfterMs, null, 'the slow body was never cut');
      assert.ok(slow.closedAfterMs >= 1000 && slow.closedAfterMs < 3000, `${slow.closedAfterMs} ms`);
      assert.ok(slow.sent < body.length, 'the body was sent whole before the cut');
      assert.doesNotMatch(slow.answer, /^HTTP\/1\.1 201/);
      const prompt = await fetch(new URL('/api/upload?name=t.obj', strict.url),
                                 { method: 'POST', body });
      assert.equal(prompt.status, 201);
    } finally {
      await strict.stop();
    }
  });

  test('a head of endless header lines is cut at 64 KiB; the server stays small and answers',
       async () => {
    // httplib bounds each header line, not their number: before the cap, 8 s of this put
    // 290 MB of headers into the server.
    const strict = await startServer(['--quiet']);
    try {
      const { hostname, port } = new URL(strict.url);
      const line = `X-Filler: ${'a'.repeat(100)}\r\n`.repeat(1000);  // 112 KB a write
      const sent = await new Promise((resolvePromise) => {
        let bytes = 0, done = false;
        const socket = net.connect(Number(port), hostname, () => {
          socket.write(`GET /api/info HTTP/1.1\r\nHost: ${new URL(strict.url).host}\r\n`);
          const more = () => {
            if (done) return;
            if (bytes > 64 * 1024 * 1024) return finish();  // never cut: give up at 64 MB
            bytes += line.length;
            if (socket.write(line)) setImmediate(more); else socket.once('drain', more);
          };
          more();
        });
        const finish = () => {
          if (done) return;
          done = true;
          socket.destroy();
          resolvePromise(bytes);
        };
        socket.on('close', finish);
        socket.on('error', finish);
      });
      assert.ok(sent < 16 * 1024 * 1024, `${sent} bytes of headers sent before the cut`);
      const status = readFileSync(`/proc/${strict.child.pid}/status`, 'utf8');
      const hwm = Number(/VmHWM:\s+(\d+) kB/.exec(status)[1]) * 1024;
      assert.ok(hwm < 100 * 1024 * 1024, `peak RSS ${hwm} bytes`);
      await serverAnswers(strict.url);
    } finally {
      await strict.stop();
    }
  });

  test('a kept-alive connection idle between requests is not cut by the head deadline',
       async () => {
    const strict = await startServer(['--quiet', '--head-timeout', '1']);
    try {
      const host = new URL(strict.url).host;
      const one = `GET /api/info HTTP/1.1\r\nHost: ${host}\r\n\r\n`;
      // Three requests on one connection, 0.7 s apart: 2.1 s in all, each head within 1 s.
      const { hostname, port } = new URL(strict.url);
      const answers = await new Promise((resolvePromise, reject) => {
        let data = '', sent = 0;
        const socket = net.connect(Number(port), hostname, () => {
          const next = () => {
            if (sent === 3) return setTimeout(() => { socket.destroy(); resolvePromise(data); }, 300);
            socket.write(one);
            ++sent;
            setTimeout(next, 700);
          };
          next();
        });
        socket.on('data', (d) => { data += d.toString('latin1'); });
        socket.on('error', reject);
      });
      assert.equal(answers.split('HTTP/1.1 200 OK').length - 1, 3, answers.slice(0, 200));
    } finally {
      await strict.stop();
    }
  });
});

describe('who may ask', () => {
  test('a Host other than this machine\'s loopback names gets 421', async () => {
    const { port } = new URL(server.url);
    for (const host of ['evil.example', `evil.example:${port}`, `127.0.0.1:${Number(port) + 1}`]) {
      const r = await rawRequest(server.url, 'GET /api/meshes HTTP/1.1', '', host);
      assert.equal(r.status, 421, host);
      assert.match(JSON.parse(r.body).error, /Host/);
    }
    for (const host of [`127.0.0.1:${port}`, `localhost:${port}`, `LOCALHOST:${port}`]) {
      const r = await rawRequest(server.url, 'GET /api/meshes HTTP/1.1', '', host);
      assert.equal(r.status, 200, host);
    }
  });

  test('a cross-origin POST gets 403, a same-origin one works, no CORS headers', async () => {
    const url = new URL('/api/upload?name=t.obj', server.url);
    const cross = await fetch(url, { method: 'POST', body: tetrahedronObj,
                                     headers: { origin: 'http://evil.example' } });
    assert.equal(cross.status, 403);
    assert.match((await cross.json()).error, /cross-origin/);
    assert.equal(cross.headers.get('access-control-allow-origin'), null);
    const same = await fetch(url, { method: 'POST', body: tetrahedronObj,
                                    headers: { origin: new URL(server.url).origin } });
    assert.equal(same.status, 201);
    assert.equal(same.headers.get('access-control-allow-origin'), null);
  });

  test('a non-loopback --host needs --allow-remote (usage error, exit 2)', async () => {
    const r = await runCli(['serve', '--port', '0', '--host', '0.0.0.0']);
    assert.equal(r.code, 2);
    assert.match(r.stderr, /--allow-remote/);
  });

  test('with --allow-remote the server warns and starts', async () => {
    const s = await startServer(['--host', '0.0.0.0', '--allow-remote', '--quiet']);
    try {
      assert.match(s.stderr(), /warning: serving on 0\.0\.0\.0 without authentication/);
    } finally {
      await s.stop();
    }
  });
});

describe('start-up', () => {
  test('a missing FILE stops the start with its name', async () => {
    const r = await runCli(['serve', '--port', '0', tankPath, '/nonexistent/nothing.stl']);
    assert.notEqual(r.code, 0);
    assert.match(r.stderr, /nothing\.stl/);
    assert.doesNotMatch(r.stdout, /listening/);
  });

  test('a FILE that is not a mesh stops the start with the reader\'s error', async () => {
    const r = await runCli(['serve', '--port', '0', new URL(import.meta.url).pathname]);
    assert.notEqual(r.code, 0);
    assert.match(r.stderr, /limits\.test\.mjs/);
  });

  test('--assets naming no folder is a usage error', async () => {
    const r = await runCli(['serve', '--port', '0', '--assets', '/nonexistent']);
    assert.equal(r.code, 2);
    assert.match(r.stderr, /--assets/);
  });
});
