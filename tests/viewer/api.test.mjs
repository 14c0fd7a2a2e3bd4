// The server of `pgamesh serve`, over HTTP on loopback: routes, status codes, limits, bad input,
// path traversal, methods, a bounded burst of concurrent requests, clean shutdown.
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { after, before, describe, test } from 'node:test';

import {
  near, objBounds, rawRequest, readObj, referenceProps, runCli, startServer, tankPath,
  tetrahedronObj,
} from './support.mjs';

let server, tankId, features;
before(async () => {
  server = await startServer();
  features = (await (await fetch(new URL('/api/info', server.url))).json()).features;
  const list = await (await fetch(new URL('/api/meshes', server.url))).json();
  tankId = list.meshes.find((m) => m.name === 'tank.obj').id;
});
after(async () => { await server.stop(); });

async function getJson(path, init) {
  const r = await fetch(new URL(path, server.url), init);
  assert.match(r.headers.get('content-type'), /^application\/json/);
  return { status: r.status, body: await r.json(), headers: r.headers };
}

function upload(text, name, url = server.url) {
  return fetch(new URL(`/api/upload?name=${encodeURIComponent(name)}`, url),
               { method: 'POST', body: text });
}

describe('assets', () => {
  test('the page and its scripts are served with their types', async () => {
    const expected = {
      '/': 'text/html', '/index.html': 'text/html', '/style.css': 'text/css',
      '/app.js': 'application/javascript', '/api.js': 'application/javascript', '/scene.js': 'application/javascript',
      '/panels.js': 'application/javascript', '/props_panel.js': 'application/javascript',
      '/fuel_panel.js': 'application/javascript', '/gauge_plot.js': 'application/javascript',
      '/vendor/three/three.module.js': 'application/javascript',
      '/vendor/three/three.core.js': 'application/javascript',
      '/vendor/three/OrbitControls.js': 'application/javascript',
    };
    for (const [path, type] of Object.entries(expected)) {
      const r = await fetch(new URL(path, server.url));
      assert.equal(r.status, 200, path);
      assert.ok(r.headers.get('content-type').startsWith(type), path);
      assert.ok((await r.text()).length > 100, path);
    }
    const html = await (await fetch(server.url)).text();
    assert.match(html, /<title>pgamesh viewer<\/title>/);
    assert.match(html, /"three": "\/vendor\/three\/three.module.js"/);  // no CDN
    assert.doesNotMatch(html, /https?:\/\//);
  });

  test('nothing outside the asset table is reachable, however the path is spelled', async () => {
    const attempts = [
      '/../../../../etc/passwd', '/%2e%2e/%2e%2e/%2e%2e/etc/passwd', '/..%2f..%2f..%2fetc/passwd',
      '/vendor/three/../../../../CMakeLists.txt', '/node_modules/three/package.json',
      '/package.json', '//etc/passwd', '/index.html/../../README.md', '/app.js%00.html',
      '/%5c..%5c..%5cCMakeLists.txt', '/vendor/', '/api/', '/index.html?x=/../../etc/passwd',
    ];
    for (const path of attempts) {
      const r = await rawRequest(server.url, `GET ${path} HTTP/1.1`);
      if (path.startsWith('/index.html?')) {
        assert.equal(r.status, 200, path);  // the query is ignored: still index.html
        assert.match(r.body, /pgamesh viewer/);
        continue;
      }
      assert.ok(r.status === 404 || r.status === 400, `${path}: ${r.status}`);
      assert.doesNotMatch(r.body, /root:|cmake_minimum_required|"dependencies"/, path);
    }
  });
});

describe('methods', () => {
  test('only GET/HEAD on pages and reads, only POST on uploads: 405 with Allow otherwise',
       async () => {
    const cases = [
      ['PUT', '/', 'GET, HEAD'], ['DELETE', '/index.html', 'GET, HEAD'],
      ['PATCH', '/api/info', 'GET, HEAD'], ['OPTIONS', '/api/meshes', 'GET, HEAD'],
      ['POST', '/api/info', 'GET, HEAD'], ['POST', '/app.js', 'GET, HEAD'],
      ['GET', '/api/upload', 'POST'], ['PUT', '/api/upload', 'POST'],
      ['DELETE', '/api/mesh/f0', 'GET, HEAD'], ['POST', '/api/mesh/f0/props', 'GET, HEAD'],
    ];
    for (const [method, path, allow] of cases) {
      const r = await fetch(new URL(path, server.url), { method });
      assert.equal(r.status, 405, `${method} ${path}`);
      assert.equal(r.headers.get('allow'), allow, `${method} ${path}`);
      assert.match((await r.json()).error, new RegExp(`method ${method} not allowed`));
    }
    const head = await fetch(new URL('/app.js', server.url), { method: 'HEAD' });
    assert.equal(head.status, 200);
  });

  test('unknown paths are 404 for every method, unknown methods 400', async () => {
    for (const method of ['GET', 'POST', 'PUT']) {
      const r = await fetch(new URL('/no/such/thing', server.url), { method });
      assert.equal(r.status, 404, method);
    }
    const r = await rawRequest(server.url, 'BREW /api/info HTTP/1.1');
    assert.equal(r.status, 400);
    const garbage = await rawRequest(server.url, 'this is not http');
    assert.equal(garbage.status, 400);
  });
});

describe('meshes', () => {
  test('/api/info names the version, upload limit and available features', async () => {
    const { status, body } = await getJson('/api/info');
    assert.equal(status, 200);
    assert.equal(body.max_upload, 64 * 1024 * 1024);
    assert.match(body.version, /^\d+\.\d+\.\d+$/);
    assert.equal(typeof body.features.props, 'boolean');
    assert.equal(typeof body.features.fuel, 'boolean');
  });

  test('the bundled tank is listed and summarised as the file says', async () => {
    const { body: list } = await getJson('/api/meshes');
    const tank = list.meshes.find((m) => m.name === 'tank.obj');
    assert.ok(tank, JSON.stringify(list));
    assert.equal(tank.origin, 'bundled');

    const obj = readObj(tankPath);
    const { status, body } = await getJson(`/api/mesh/${tank.id}`);
    assert.equal(status, 200);
    assert.equal(body.name, 'tank.obj');
    assert.equal(body.format, 'obj');
    assert.equal(body.vertices, obj.vertices.length);
    assert.equal(body.faces, obj.faces.length);
    assert.equal(body.triangles, obj.faces.length);
    const bounds = objBounds(obj);
    assert.deepEqual(body.bounds, bounds);
    assert.deepEqual(body.drawing_origin, [0, 1, 2].map((k) => (bounds.min[k] + bounds.max[k]) / 2));
  });

  test('the geometry holds every vertex and face of the file', async () => {
    const obj = readObj(tankPath);
    const { body: summary } = await getJson(`/api/mesh/${tankId}`);
    const r = await fetch(new URL(`/api/mesh/${tankId}/geometry`, server.url));
    assert.equal(r.status, 200);
    const buffer = await r.arrayBuffer();
    const head = new DataView(buffer, 0, 8);
    const v = head.getUint32(0, true), t = head.getUint32(4, true);
    assert.equal(v, obj.vertices.length);
    assert.equal(t, obj.faces.length);
    assert.equal(buffer.byteLength, 8 + 12 * v + 12 * t);
    const positions = new Float32Array(buffer, 8, 3 * v);
    const indices = new Uint32Array(buffer, 8 + 12 * v, 3 * t);
    obj.vertices.forEach((p, i) => {
      for (let k = 0; k < 3; ++k)
        assert.ok(Math.abs(positions[3 * i + k] + summary.drawing_origin[k] - p[k]) < 1e-6);
    });
    assert.deepEqual(Array.from(indices), obj.faces.flat());
  });

  test('an upload is parsed, stored and can be read back by its id', async () => {
    const r = await upload(tetrahedronObj, 'dir/../tetra.obj');
    assert.equal(r.status, 201);
    const body = await r.json();
    assert.equal(body.name, 'tetra.obj');  // only the last path component is kept
    assert.match(body.id, /^u\d+$/);
    assert.equal(body.vertices, 4);
    assert.equal(body.faces, 4);
    assert.deepEqual(body.bounds, { min: [0, 0, 0], max: [1, 1, 1] });
    const again = await getJson(`/api/mesh/${body.id}`);
    assert.equal(again.status, 200);
    assert.deepEqual(again.body, body);
  });

  test('a quad is drawn as two triangles', async () => {
    const r = await upload('v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n', 'quad.obj');
    assert.equal(r.status, 201);
    const body = await r.json();
    assert.equal(body.faces, 1);
    assert.equal(body.triangles, 2);
  });

  test('bad uploads get 400 with the upload named, and the server keeps serving', async () => {
    const bad = [
      ['notes.txt', 'this is not a mesh at all\n'],
      ['broken.obj', 'v 0 0 0\nv 1 0 0\nf 1 2 9\n'],
      ['binary.stl', Buffer.from([0xff, 0xfe, 0x00, 0x01, 0x02, 0x03, 0x80, 0x90])],
    ];
    for (const [name, content] of bad) {
      const r = await upload(content, name);
      assert.equal(r.status, 400, name);
      const { error } = await r.json();
      assert.ok(error.startsWith(name), `${name}: ${error}`);
    }
    const empty = await upload('', 'empty.stl');
    assert.equal(empty.status, 400);
    assert.match((await empty.json()).error, /empty/);
    assert.equal((await fetch(new URL('/api/info', server.url))).status, 200);
  });

  test('unknown or malformed mesh ids are 404', async () => {
    for (const id of ['u999999', 'f999', 'x1', 'f', 'f1a', 'u-1']) {
      const r = await fetch(new URL(`/api/mesh/${id}`, server.url));
      assert.equal(r.status, 404, id);
    }
  });

  test('only the most recent uploads are kept', async () => {
    const ids = [];
    for (let i = 0; i < 10; ++i) ids.push((await (await upload(tetrahedronObj, `t${i}.obj`)).json()).id);
    assert.equal((await fetch(new URL(`/api/mesh/${ids[0]}`, server.url))).status, 404);
    assert.equal((await fetch(new URL(`/api/mesh/${ids[9]}`, server.url))).status, 200);
  });
});

describe('mass properties', () => {
  test('the tetrahedron: closed forms at a density', async () => {
    const { id } = await (await upload(tetrahedronObj, 'tetra.obj')).json();
    const { status, body } = await getJson(`/api/mesh/${id}/props?density=2.5`);
    assert.equal(status, 200);
    assert.ok(near(body.volume, 1 / 6, 1, 1e-15));
    assert.ok(near(body.area, 1.5 + Math.sqrt(3) / 2, 1, 1e-15));
    assert.equal(body.density, 2.5);
    assert.ok(near(body.mass, 2.5 / 6, 1, 1e-15));
    assert.ok(near(body.center_of_mass, [0.25, 0.25, 0.25], 1, 1e-15));
    // I = ρ (tr C − C), C = ∫ r rᵀ dV − V c cᵀ, with ∫x² dV = 1/60 and ∫xy dV = 1/120 about
    // the origin for the unit right tetrahedron.
    const d = 2.5 * (2 / 60 - 2 * (1 / 6) / 16), o = -2.5 * (1 / 120 - (1 / 6) / 16);
    assert.ok(near(body.inertia_com, [[d, o, o], [o, d, o], [o, o, d]], 1, 1e-14));
    assert.equal(body.gap_area, 0);
  });

  test('the tank against the classical divergence-theorem sums', async () => {
    const { body } = await getJson(`/api/mesh/${tankId}/props?density=800`);
    const ref = referenceProps(readObj(tankPath), 800);
    assert.ok(near(body.volume, ref.volume, ref.volume));
    assert.ok(near(body.area, ref.area, ref.area));
    assert.ok(near(body.mass, ref.mass, ref.mass));
    assert.ok(near(body.center_of_mass, ref.center_of_mass, 1.6));
    assert.ok(near(body.inertia_com, ref.inertia_com, ref.inertia_com[1][1]));
    // Each principal axis is an eigenvector of the reference tensor with its moment.
    body.principal_axes.forEach((a, i) => {
      const Ia = ref.inertia_com.map((row) => row[0] * a[0] + row[1] * a[1] + row[2] * a[2]);
      assert.ok(near(Ia, a.map((x) => body.principal_moments[i] * x), ref.inertia_com[1][1]));
    });
    assert.ok(body.principal_moments[0] <= body.principal_moments[1]);
    assert.ok(body.principal_moments[1] <= body.principal_moments[2]);
  });

  test('an open mesh: not closed, its boundary edges and gap', async () => {
    const open = tetrahedronObj.replace('f 2 3 4\n', '');
    const { id } = await (await upload(open, 'open.obj')).json();
    const { body } = await getJson(`/api/mesh/${id}/props`);
    assert.equal(body.closed, false);
    assert.equal(body.boundary_edges, 3);
    assert.ok(near(body.gap_area, Math.sqrt(3) / 2, 1, 1e-15));
    const b = (await getJson(`/api/mesh/${id}/boundary`)).body;
    assert.equal(b.boundary_edges, 3);
    const ends = b.segments.map((s) => [s.slice(0, 3), s.slice(3)].map((p) => p.join(',')).sort()
      .join(' ')).sort();
    assert.deepEqual(ends, ['0,0,1 0,1,0', '0,0,1 1,0,0', '0,1,0 1,0,0']);
    assert.equal(b.loops.length, 1);
    assert.ok(near(b.loops[0].area, Math.sqrt(3) / 2, 1, 1e-15));
    assert.ok(near(b.loops[0].perimeter, 3 * Math.SQRT2, 1, 1e-15));
    const closed = (await getJson(`/api/mesh/${tankId}/props`)).body;
    assert.equal(closed.closed, true);
    assert.equal(closed.boundary_edges, 0);
    assert.equal(closed.orientation_consistent, true);
  });

  test('bad densities are 400, unknown meshes 404', async () => {
    for (const q of ['density=abc', 'density=-1', 'density=', 'density=1e999', 'density=nan']) {
      const r = await fetch(new URL(`/api/mesh/${tankId}/props?${q}`, server.url));
      assert.equal(r.status, 400, q);
    }
    assert.equal((await fetch(new URL('/api/mesh/u999999/props', server.url))).status, 404);
  });
});

describe('fuel', () => {
  const fuel = async (query) => getJson(`/api/mesh/${tankId}/fuel?${query}`);

  test('level at the axis of the symmetric tank: half the volume, the same as pgamesh fuel',
       async (t) => {
    if (!features.fuel) return t.skip('this build serves no fuel');
    const { status, body } = await fuel('level=0.6');
    assert.equal(status, 200);
    assert.deepEqual(body.up, [0, 0, 1]);
    assert.equal(body.lowest, 0);
    assert.equal(body.highest, 1.2);
    const whole = referenceProps(readObj(tankPath)).volume;
    assert.ok(near(body.tank_volume, whole, whole));
    assert.ok(near(body.volume, whole / 2, whole, 1e-12));
    assert.ok(near(body.fraction, 0.5, 1, 1e-12));
    assert.ok(body.center_of_mass[2] < 0.6 && body.center_of_mass[2] > 0.2);
    // The free surface at the axis is the tank's widest section: a 3.2 × 1.2 m stadium
    // (faceted), between the inscribed polygon's area and the smooth one's.
    assert.ok(body.surface_area < 2 * 1.2 + Math.PI * 0.36 && body.surface_area > 3.1);
    const cli = await runCli(['fuel', tankPath, '--level', '0.6', '--json']);
    if (cli.code === 0) {
      const c = JSON.parse(cli.stdout);
      // The server asks the hierarchy, the command the full pass: equal up to rounding.
      for (const k of ['level', 'volume', 'fraction', 'wetted_area', 'surface_area'])
        assert.ok(near(body[k], c[k], Math.abs(c[k]), 1e-12), k);
      assert.ok(near(body.center_of_mass, c.center_of_mass, 1.6, 1e-12));
    }
  });

  test('pitch and roll: the same figures as pgamesh fuel --pitch --roll', async (t) => {
    if (!features.fuel) return t.skip('this build serves no fuel');
    const { body } = await fuel('pitch=7.5&roll=-4&level=0.7');
    const cli = await runCli(['fuel', tankPath, '--pitch', '7.5', '--roll', '-4', '--level', '0.7',
                              '--json']);
    assert.equal(cli.code, 0, cli.stderr);
    const c = JSON.parse(cli.stdout);
    assert.deepEqual(body.up, c.up);
    const scale = body.tank_volume;
    assert.ok(near(body.volume, c.volume, scale, 1e-12));
    assert.ok(near(body.center_of_mass, c.center_of_mass, 1.6, 1e-12));
    assert.ok(near(body.wetted_area, c.wetted_area, c.wetted_area, 1e-12));
    assert.ok(near(body.surface_area, c.surface_area, c.surface_area, 1e-12));
  });

  test('fill to a volume gives the level that holds it', async (t) => {
    if (!features.fuel) return t.skip('this build serves no fuel');
    const { body } = await fuel('pitch=3&volume=1.25');
    assert.ok(near(body.volume, 1.25, 1.25, 1e-12));
    assert.equal(body.target_volume, 1.25);
    const back = await fuel(`pitch=3&level=${body.level}`);
    assert.ok(near(back.body.volume, 1.25, 1.25, 1e-12));
  });

  test('the gauge table rises from empty to full', async (t) => {
    if (!features.fuel) return t.skip('this build serves no fuel');
    const { status, body } = await getJson(`/api/mesh/${tankId}/fuel/table?n=16&roll=10`);
    assert.equal(status, 200);
    assert.equal(body.rows.length, 17);
    assert.equal(body.rows[0].level, body.lowest);
    assert.equal(body.rows[16].level, body.highest);
    assert.ok(near(body.rows[0].volume, 0, body.tank_volume, 1e-15));
    assert.ok(near(body.rows[16].volume, body.tank_volume, body.tank_volume, 1e-12));
    for (let i = 1; i < 17; ++i) assert.ok(body.rows[i].volume >= body.rows[i - 1].volume);
    const mid = await fuel(`roll=10&level=${body.rows[8].level}`);
    assert.ok(near(mid.body.volume, body.rows[8].volume, body.tank_volume, 1e-12));
  });

  test('bad queries are 400, impossible ones 422, open meshes 422 with the reason', async (t) => {
    if (!features.fuel) return t.skip('this build serves no fuel');
    for (const q of ['level=abc', '', 'level=1&volume=1', 'pitch=400&level=0.5', 'roll=x&level=1'])
      assert.equal((await fuel(q)).status, 400, q);
    for (const q of ['n=0', 'n=5000', 'n=2.5'])
      assert.equal((await getJson(`/api/mesh/${tankId}/fuel/table?${q}`)).status, 400, q);
    const below = await fuel('level=-1');
    assert.equal(below.status, 422);
    assert.match(below.body.error, /below the tank/);
    const over = await fuel('volume=1000');
    assert.equal(over.status, 422);
    assert.match(over.body.error, /volume 1000/);
    const open = tetrahedronObj.replace('f 2 3 4\n', '');
    const { id } = await (await upload(open, 'open.obj')).json();
    const r = await getJson(`/api/mesh/${id}/fuel?level=0.5`);
    assert.equal(r.status, 422);
    assert.match(r.body.error, /^open\.obj: not a closed, outward-oriented tank; open: 3 boundary edges/);
    const inside = tetrahedronObj.replace('f 1 3 2', 'f 1 2 3').replace('f 1 2 4', 'f 1 4 2')
      .replace('f 1 4 3', 'f 1 3 4').replace('f 2 3 4', 'f 2 4 3');
    const inv = await (await upload(inside, 'inside-out.obj')).json();
    const r2 = await getJson(`/api/mesh/${inv.id}/fuel?level=0.5`);
    assert.equal(r2.status, 422);
    assert.match(r2.body.error, /inside out/);
  });

  test('check lists intersecting faces: two overlapping cubes, as pgamesh check finds them',
       async () => {
    const cube = (o) => {
      const v = [];
      for (const z of [0, 2]) for (const y of [0, 2]) for (const x of [0, 2])
        v.push(`v ${x + o} ${y + o} ${z + o}`);
      return v.join('\n') + '\n';
    };
    // Faces of a cube with vertices 1..8 (x fastest), outward; the second cube adds 8.
    const faces = (k) => [[1, 3, 4, 2], [5, 6, 8, 7], [1, 2, 6, 5], [3, 7, 8, 4], [1, 5, 7, 3],
                          [2, 4, 8, 6]].map((f) => 'f ' + f.map((i) => i + k).join(' ')).join('\n');
    const text = cube(0) + cube(1) + faces(0) + '\n' + faces(8) + '\n';
    const { id } = await (await upload(text, 'overlap.obj')).json();
    const c = await getJson(`/api/mesh/${id}/check`);
    assert.equal(c.status, 200);
    const file = join(tmpdir(), `pgamesh-overlap-${process.pid}.obj`);
    writeFileSync(file, text);
    const cli = JSON.parse((await runCli(['check', file, '--json'])).stdout);
    assert.ok(cli.self_intersecting_pairs > 0);
    assert.equal(c.body.self_intersecting_pairs, cli.self_intersecting_pairs);
    const p = await getJson(`/api/mesh/${id}/props`);
    assert.equal(p.body.volume_valid, false);
    assert.ok(p.body.reasons.some((r) => /self-intersecting/.test(r)), p.body.reasons.join('; '));
  });

  test('an upload closed only by a weld is gauged with weld_tolerance', async (t) => {
    if (!features.fuel) return t.skip('this build serves no fuel');
    // A unit cube whose face x = 1 has vertices of its own, 4e-9 off the others.
    const seamCube = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n' +
      'v 1.000000004 0 0\nv 1.000000004 1 0\nv 1.000000004 1 1\nv 1.000000004 0 1\n' +
      'f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\n' +
      'f 1 5 8\nf 1 8 4\nf 9 10 11\nf 9 11 12\n';
    const asRead = await (await upload(seamCube, 'seam.obj')).json();
    assert.equal((await getJson(`/api/mesh/${asRead.id}/fuel?volume=0.5`)).status, 422);
    const r = await fetch(new URL('/api/upload?name=seam.obj&weld_tolerance=1e-6', server.url),
                          { method: 'POST', body: seamCube });
    assert.equal(r.status, 201);
    const welded = await r.json();
    assert.equal(welded.weld_tolerance, 1e-6);
    const props = await getJson(`/api/mesh/${welded.id}/props`);
    assert.equal(props.body.closed, true);
    const f = await getJson(`/api/mesh/${welded.id}/fuel?volume=0.5`);
    assert.equal(f.status, 200);
    assert.ok(near(f.body.level, 0.5, 1, 1e-12), `${f.body.level}`);
    const bad = await fetch(new URL('/api/upload?name=s.obj&weld_tolerance=-1', server.url),
                            { method: 'POST', body: seamCube });
    assert.equal(bad.status, 400);
  });
});

describe('limits and load', () => {
  test('uploads over --max-upload get 413 and the server stays up', async () => {
    const small = await startServer(['--max-upload', '1K', '--quiet']);
    try {
      const info = await (await fetch(new URL('/api/info', small.url))).json();
      assert.equal(info.max_upload, 1024);
      const big = `# ${'x'.repeat(4000)}\n${tetrahedronObj}`;
      const r = await upload(big, 'big.obj', small.url);
      assert.equal(r.status, 413);
      assert.match((await r.json()).error, /upload limit of 1024 bytes/);
      const ok = await upload(tetrahedronObj, 'small.obj', small.url);
      assert.equal(ok.status, 201);
    } finally {
      await small.stop();
    }
  });

  test('a burst of 240 concurrent requests, 24 in flight: every answer complete', async () => {
    const appJs = await (await fetch(new URL('/app.js', server.url))).text();
    const kinds = [
      async () => {
        const r = await fetch(new URL(`/api/mesh/${tankId}`, server.url));
        return r.status === 200 && (await r.json()).faces === 2976;
      },
      async () => {
        const r = await fetch(new URL('/app.js', server.url));
        return r.status === 200 && (await r.text()) === appJs;
      },
      async () => {
        const r = await upload(tetrahedronObj, 'burst.obj');
        return r.status === 201 && (await r.json()).faces === 4;
      },
      async () => {
        const r = await fetch(new URL(`/api/mesh/${tankId}/geometry`, server.url));
        return r.status === 200 && (await r.arrayBuffer()).byteLength === 8 + 12 * 1490 + 12 * 2976;
      },
    ];
    const total = 240, inFlight = 24;
    let next = 0, good = 0;
    const worker = async () => {
      while (next < total) {
        const i = next++;
        if (await kinds[i % kinds.length]()) ++good;
      }
    };
    await Promise.all(Array.from({ length: inFlight }, worker));
    assert.equal(good, total);
  });
});

describe('command line', () => {
  test('SIGTERM stops the server cleanly', async () => {
    const s = await startServer(['--quiet']);
    const { code, signal } = await s.stop();
    assert.equal(signal, null);
    assert.equal(code, 0);
    assert.match(s.stderr(), /stopped/);
  });

  test('a port in use is an error, bad options are usage errors', async () => {
    const port = new URL(server.url).port;
    const busy = await runCli(['serve', '--port', port]);
    assert.equal(busy.code, 1);
    assert.match(busy.stderr, /cannot listen on 127\.0\.0\.1/);
    for (const args of [['--port', '70000'], ['--max-upload', 'lots'], ['--bogus']]) {
      const r = await runCli(['serve', ...args]);
      assert.equal(r.code, 2, args.join(' '));
    }
    const help = await runCli(['serve', '--help']);
    assert.equal(help.code, 0);
    assert.match(help.stdout, /--max-upload/);
  });

  test('files named on the command line are listed first (bad ones: limits.test.mjs)',
       async () => {
    const s = await startServer(['--quiet', tankPath]);
    try {
      const list = (await (await fetch(new URL('/api/meshes', s.url))).json()).meshes;
      assert.deepEqual(list.slice(0, 1).map((m) => [m.name, m.origin]),
                       [['tank.obj', 'command line']]);
      const r = await fetch(new URL(`/api/mesh/${list[0].id}`, s.url));
      assert.equal(r.status, 200);
    } finally {
      await s.stop();
    }
  });
});

// The committed tank really is what the generator writes (the fuel tests rely on it).
test('tank.obj is a closed, consistently oriented triangle mesh', () => {
  const { faces } = readObj(tankPath);
  const directed = new Set();
  for (const f of faces)
    for (let k = 0; k < 3; ++k) {
      const e = `${f[k]},${f[(k + 1) % 3]}`;
      assert.ok(!directed.has(e), `edge ${e} used twice in one direction`);
      directed.add(e);
    }
  for (const e of directed) {
    const [a, b] = e.split(',');
    assert.ok(directed.has(`${b},${a}`), `edge ${e} has no opposite: open`);
  }
  assert.ok(readFileSync(tankPath).length < 200 * 1024);
});
