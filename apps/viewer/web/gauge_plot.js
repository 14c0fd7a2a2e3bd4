// The gauge curve as SVG: fuel volume (vertical) against level (horizontal) for one attitude,
// with the current level marked. Points come from the server's gauge table.
import { fmt } from './panels.js';

const NS = 'http://www.w3.org/2000/svg';
const W = 360, H = 220, LEFT = 52, RIGHT = 10, TOP = 10, BOTTOM = 34;

function el(name, attrs, text) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text !== undefined) e.textContent = text;
  return e;
}

// levels and volumes: equal-length arrays (levels ascending). current: {level, volume} or null.
export function drawGaugePlot(svg, levels, volumes, current) {
  const x0 = levels[0], x1 = levels[levels.length - 1];
  const y1 = Math.max(...volumes) || 1;
  const sx = (x) => LEFT + (W - LEFT - RIGHT) * (x1 > x0 ? (x - x0) / (x1 - x0) : 0.5);
  const sy = (y) => H - BOTTOM - (H - TOP - BOTTOM) * (y / y1);
  const parts = [];
  for (let i = 0; i <= 4; ++i) {
    const y = (y1 * i) / 4, x = x0 + ((x1 - x0) * i) / 4;
    parts.push(el('line', { class: 'grid', x1: LEFT, x2: W - RIGHT, y1: sy(y), y2: sy(y) }));
    parts.push(el('text', { x: LEFT - 4, y: sy(y) + 4, 'text-anchor': 'end' }, fmt(y)));
    parts.push(el('text', { x: sx(x), y: H - BOTTOM + 14, 'text-anchor': 'middle' }, fmt(x)));
  }
  parts.push(el('line', { class: 'axis', x1: LEFT, x2: LEFT, y1: TOP, y2: H - BOTTOM }));
  parts.push(el('line', { class: 'axis', x1: LEFT, x2: W - RIGHT, y1: H - BOTTOM,
                          y2: H - BOTTOM }));
  parts.push(el('text', { x: (LEFT + W - RIGHT) / 2, y: H - 4, 'text-anchor': 'middle' },
                'level'));
  parts.push(el('text', { x: 12, y: (TOP + H - BOTTOM) / 2, 'text-anchor': 'middle',
                          transform: `rotate(-90 12 ${(TOP + H - BOTTOM) / 2})` }, 'volume'));
  const d = levels.map((x, i) => `${i ? 'L' : 'M'}${sx(x).toFixed(2)},${sy(volumes[i]).toFixed(2)}`);
  parts.push(el('path', { class: 'curve', d: d.join('') }));
  if (current) {
    parts.push(el('line', { class: 'cursor', x1: sx(current.level), x2: sx(current.level),
                            y1: TOP, y2: H - BOTTOM }));
    parts.push(el('circle', { class: 'current', cx: sx(current.level), cy: sy(current.volume),
                              r: 4, 'data-level': current.level,
                              'data-volume': current.volume }));
  }
  svg.replaceChildren(...parts);
}
