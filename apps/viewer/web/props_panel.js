// The mass-properties panel: figures from the library (the same JSON as `pgamesh props --json`),
// the centre of mass as a marker, the principal axes as arrows, and the boundary edges of an open
// mesh highlighted.
import * as api from './api.js';
import { setFigure } from './panels.js';

const AXIS_COLORS = [0xe4572e, 0x29bf12, 0x2e86de];  // moments ascending: smallest red

export class PropsPanel {
  constructor(state, onStatus) {
    this.state = state;
    this.onStatus = onStatus;
    this.seq = 0;
    this.input = document.getElementById('density');
    this.input.addEventListener('change', () => this.update());
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
      if (p.boundary_edges > 0 && this.state.info.features.check) {
        const b = await api.getBoundary(mesh.id);
        if (seq === this.seq && view) view.setLayer('boundary', view.segments(
          b.segments.map((s) => [s.slice(0, 3), s.slice(3, 6)]), 0xff00aa));
      }
    } catch (e) {
      if (seq === this.seq) this.onStatus(e.message);
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
    view.setLayer('boundary', null);
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
