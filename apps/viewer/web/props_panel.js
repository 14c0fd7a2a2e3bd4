// The mass-properties panel: figures from the library (the same JSON as `pgamesh props --json`),
// the centre of mass as a marker, the principal axes as arrows (the principal frame's gizmo), and
// what `pgamesh check` finds — boundary, non-manifold and inconsistently oriented edges —
// highlighted and listed, with a Repair action (`pgamesh repair`).
import * as api from './api.js';
import { setFigure } from './panels.js';

const AXIS_COLORS = [0xe4572e, 0x29bf12, 0x2e86de];  // moments ascending: smallest red
const EDGE_COLORS = { boundary: 0xff00aa, nonmanifold: 0xff8c00, inconsistent: 0x0a9396 };
const INTERSECTING_COLOR = 0xe01e37;

function plural(n, word) {
  return `${n} ${word}${n === 1 ? '' : 's'}`;
}

export class PropsPanel {
  // onRepaired(summary, report): the Repair action made a new mesh, to be opened.
  constructor(state, onStatus, onRepaired) {
    this.state = state;
    this.onStatus = onStatus;
    this.onRepaired = onRepaired;
    this.seq = 0;
    this.input = document.getElementById('density');
    this.input.addEventListener('change', () => this.update());
    document.getElementById('repair-button').addEventListener('click', () => this.repair());
  }

  // Recomputes for the current mesh; resolves once the figures (or an error) are shown.
  async update() {
    const { mesh, view } = this.state;
    if (!mesh) return;
    const seq = ++this.seq;
    const density = Number(this.input.value);
    if (!(density >= 0) || !Number.isFinite(density)) {
      this.onStatus(`density must be a number ≥ 0, not "${this.input.value}"`);
      return;
    }
    try {
      const p = await api.getProps(mesh.id, density);
      if (seq !== this.seq) return;
      // Figures of an open or inconsistent surface are shown, with why they are not a solid's.
      this.onStatus(p.volume_valid === false
        ? `Not the figures of a solid: ${p.reasons.join('; ')}` : null);
      this.show(p);
      if (view) this.draw(p);
      document.getElementById('defects').hidden = true;
      if (this.state.info.features.check) {
        const c = await api.getCheck(mesh.id);
        if (seq !== this.seq) return;
        this.showDefects(c, p);
        if (view)
          for (const [kind, key] of [['boundary', 'segments'], ['nonmanifold', 'nonmanifold_segments'],
                                     ['inconsistent', 'inconsistent_segments']])
            view.setLayer(kind, c[key].length ? view.segments(
              c[key].map((s) => [s.slice(0, 3), s.slice(3, 6)]), EDGE_COLORS[kind]) : null);
        if (view)
          view.setLayer('intersecting', c.self_intersecting_faces.length
            ? view.faces(c.self_intersecting_faces, INTERSECTING_COLOR) : null);
      }
    } catch (e) {
      if (seq === this.seq) this.onStatus(e.message);
    }
  }

  // The defects' counts, each with its colour in the view; the Repair button when there is
  // something to repair.
  showDefects(c, p) {
    const items = [];
    const add = (n, text, key) => {
      if (n > 0) items.push({ text, key });
    };
    add(c.boundary_edges, `${plural(c.boundary_edges, 'boundary edge')} in ` +
        `${plural(c.loops.length, 'hole')}, gap area ${c.gap_area.toPrecision(6)}`, 'boundary');
    add(c.nonmanifold_edges, plural(c.nonmanifold_edges, 'non-manifold edge'), 'nonmanifold');
    add(c.inconsistent_edges, `${plural(c.inconsistent_edges, 'inconsistently oriented edge')} ` +
        '(flipped faces)', 'inconsistent');
    add(c.inward_components, `${plural(c.inward_components, 'closed part')} facing inward`);
    add(c.self_intersecting_pairs,
        `${c.self_intersections_complete === false ? 'at least ' : ''}` +
        `${plural(c.self_intersecting_pairs, 'pair')} of intersecting faces`, 'intersecting');
    add(c.duplicated_faces, plural(c.duplicated_faces, 'duplicated face'));
    add(c.zero_area_faces, plural(c.zero_area_faces, 'zero-area face'));
    if (c.cavity_components > 0)
      items.push({ text: `${plural(c.cavity_components, 'cavity')} (inward by design)` });
    const list = document.getElementById('defects-list');
    list.replaceChildren(...items.map(({ text, key }) => {
      const li = document.createElement('li');
      if (key) {
        const k = document.createElement('span');
        k.className = `key ${key}`;
        li.append(k, ' ');
      }
      li.append(text);
      return li;
    }));
    list.dataset.counts = JSON.stringify({
      boundary_edges: c.boundary_edges, nonmanifold_edges: c.nonmanifold_edges,
      inconsistent_edges: c.inconsistent_edges, inward_components: c.inward_components,
      duplicated_faces: c.duplicated_faces, zero_area_faces: c.zero_area_faces,
      self_intersecting_pairs: c.self_intersecting_pairs,
    });
    const repairable = p.volume_valid === false;
    document.getElementById('repair-button').hidden = !repairable;
    document.getElementById('defects').hidden = items.length === 0 && !repairable;
  }

  // Repairs the current mesh on the server and opens the result, with what changed.
  async repair() {
    const { mesh } = this.state;
    if (!mesh) return;
    const status = document.getElementById('repair-status');
    status.textContent = 'Repairing…';
    try {
      const { mesh: repaired, repair: r } = await api.repair(mesh.id);
      const removed = r.removed_faces.collapsed + r.removed_faces.duplicated +
                      2 * r.removed_faces.double_wall_pairs;
      const summary = `Repaired ${mesh.name}: ${plural(r.weld.merged, 'vertex')} merged, ` +
        `${plural(removed, 'face')} removed, ${plural(r.reversed_faces.count, 'face')} reversed, ` +
        `${r.holes.capped} of ${plural(r.holes.count, 'hole')} capped` +
        (r.holes.refused ? ` (${r.holes.list.filter((h) => !h.capped)
          .map((h) => h.refused).join('; ')})` : '') +
        `; the result is ${r.result.volume_valid ? 'a solid' : 'not a solid: ' +
          r.result.reasons.join('; ')}.`;
      status.textContent = '';
      await this.onRepaired(repaired, summary);
    } catch (e) {
      status.textContent = e.message;
    }
  }

  show(p) {
    setFigure('props-area', p.area);
    setFigure('props-volume', p.volume);
    setFigure('props-mass', p.mass);
    setFigure('props-com', p.center_of_mass);
    setFigure('props-inertia', p.inertia_com);
    setFigure('props-principal', p.principal_moments);
    if (p.principal_degenerate)
      document.getElementById('props-principal').textContent +=
        ' — (nearly) equal moments: the axes in their plane are not unique';
    setFigure('props-axes', p.principal_axes);
    // Topology fields come with the topology library; shown only when the server sends them.
    const topology = 'closed' in p;
    for (const id of ['props-closed', 'props-boundary-edges']) {
      document.getElementById(id).hidden = !topology;
      document.getElementById(id).previousElementSibling.hidden = !topology;
    }
    if (topology) {
      setFigure('props-closed', p.closed,
                p.closed ? 'yes' : 'no: the figures are those of an open surface');
      setFigure('props-boundary-edges', p.boundary_edges);
    }
    setFigure('props-gap-area', p.gap_area);
  }

  draw(p) {
    const view = this.state.view;
    for (const kind of [...Object.keys(EDGE_COLORS), 'intersecting']) view.setLayer(kind, null);
    const com = p.center_of_mass;
    if (!com) {  // null when undefined (docs/json.md)
      view.setLayer('com', null);
      view.setLayer('axes', null);
      return;
    }
    view.setLayer('com', view.marker(com, 0xd62839));
    const length = 0.3 * view.size;
    view.setLayer('axes', view.arrows(com, p.principal_axes, [length, length, length],
                                      AXIS_COLORS));
  }
}
