// The server's JSON API (docs/viewer.md). Every call resolves to parsed JSON or throws an Error
// whose message is the server's own explanation.

async function parse(response) {
  const type = response.headers.get('Content-Type') || '';
  const body = type.startsWith('application/json') ? await response.json() : null;
  if (!response.ok) {
    const why = body && body.error ? body.error : `HTTP ${response.status}`;
    throw new Error(why);
  }
  return body;
}

export async function getInfo() {
  return parse(await fetch('/api/info'));
}

export async function listMeshes() {
  return (await parse(await fetch('/api/meshes'))).meshes;
}

export async function getMesh(id) {
  return parse(await fetch(`/api/mesh/${encodeURIComponent(id)}`));
}

// The triangles to draw: positions relative to the summary's drawing_origin, and indices.
export async function getGeometry(id) {
  const response = await fetch(`/api/mesh/${encodeURIComponent(id)}/geometry`);
  if (!response.ok) await parse(response);
  const buffer = await response.arrayBuffer();
  const head = new DataView(buffer, 0, 8);
  const vertexCount = head.getUint32(0, true);
  const triangleCount = head.getUint32(4, true);
  const positions = new Float32Array(buffer, 8, 3 * vertexCount);
  const indices = new Uint32Array(buffer, 8 + 12 * vertexCount, 3 * triangleCount);
  return { positions, indices };
}

// Sends a file's bytes as they are; the server detects the format from the content.
export async function upload(file) {
  const response = await fetch(`/api/upload?name=${encodeURIComponent(file.name)}`, {
    method: 'POST',
    headers: { 'Content-Type': 'application/octet-stream' },
    body: file,
  });
  return parse(response);
}

function query(params) {
  return new URLSearchParams(Object.entries(params).map(([k, v]) => [k, String(v)])).toString();
}

// Mass properties (pgamesh props --json) at a density.
export async function getProps(id, density) {
  return parse(await fetch(`/api/mesh/${encodeURIComponent(id)}/props?${query({ density })}`));
}

// What check finds: boundary, non-manifold and inconsistent edges as segments
// [[ax, ay, az, bx, by, bz], ...] (capped), the defects' counts and the notes.
export async function getCheck(id) {
  return parse(await fetch(`/api/mesh/${encodeURIComponent(id)}/check`));
}

// Runs pgamesh repair on the mesh; resolves to {mesh: the repaired mesh's summary, repair: the
// report of pgamesh repair --json}.
export async function repair(id) {
  return parse(await fetch(`/api/mesh/${encodeURIComponent(id)}/repair`, { method: 'POST' }));
}

// The fuel (pgamesh fuel --json) for an attitude and either {level} or {volume}.
export async function getFuel(id, params) {
  return parse(await fetch(`/api/mesh/${encodeURIComponent(id)}/fuel?${query(params)}`));
}

// The gauge table for an attitude: n + 1 levels from the lowest to the highest point.
export async function getFuelTable(id, params) {
  return parse(await fetch(`/api/mesh/${encodeURIComponent(id)}/fuel/table?${query(params)}`));
}
