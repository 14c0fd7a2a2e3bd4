// Filling the side panels. Every figure element keeps the full-precision value in data-value (JSON
// text) and shows a rounded one, so tests and copy-paste get every digit.

// A number with 6 significant digits for display (full precision stays in data-value).
export function fmt(x) {
  if (x === null) return '—';
  if (typeof x !== 'number') return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  if (a >= 1e-4 && a < 1e7) return Number(x.toPrecision(6)).toString();
  return x.toExponential(5);
}

// Entries below 1e-12 of the largest one are rounding noise of a zero: shown as 0 (the exact
// value stays in data-value).
function snap(values) {
  const big = Math.max(...values.map((x) => (typeof x === 'number' ? Math.abs(x) : 0)));
  return (x) => (typeof x === 'number' && Math.abs(x) < 1e-12 * big ? 0 : x);
}

export function fmtVector(v) {
  const s = snap(v);
  return `(${v.map((x) => fmt(s(x))).join(', ')})`;
}

export function fmtMatrix(m) {
  const s = snap(m.flat());
  return m.map((row) => `[${row.map((x) => fmt(s(x))).join(', ')}]`).join('\n');
}

// Sets the figure with this id: shown text and the exact value.
export function setFigure(id, value, text) {
  const el = document.getElementById(id);
  el.dataset.value = JSON.stringify(value);
  el.textContent = text !== undefined ? text
    : Array.isArray(value) ? (Array.isArray(value[0]) ? fmtMatrix(value) : fmtVector(value))
    : fmt(value);
}

export function clearFigures(root) {
  for (const dd of root.querySelectorAll('dd')) {
    dd.textContent = '';
    delete dd.dataset.value;
  }
}

export function fillMeshPanel(summary) {
  document.getElementById('mesh-name').textContent = summary.name;
  setFigure('mesh-format', summary.format,
            summary.format + (summary.single_precision ? ' (float32 coordinates)' : ''));
  setFigure('mesh-vertices', summary.vertices);
  setFigure('mesh-faces', summary.faces);
  setFigure('mesh-triangles', summary.triangles);
  setFigure('mesh-bounds-min', summary.bounds.min);
  setFigure('mesh-bounds-max', summary.bounds.max);
  const list = document.getElementById('mesh-warnings');
  list.replaceChildren(...summary.warnings.map((w) => {
    const li = document.createElement('li');
    li.textContent = w;
    return li;
  }));
}

// The message box: kind 'error' (red) or 'info'; null text hides it.
export function showMessage(text, kind = 'error') {
  const box = document.getElementById('message');
  box.hidden = !text;
  box.textContent = text || '';
  box.className = kind;
  box.dataset.kind = text ? kind : '';
}
