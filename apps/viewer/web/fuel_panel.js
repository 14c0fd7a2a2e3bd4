// The fuel panel: pitch, roll and level controls, figures from the library (the same JSON as
// `pgamesh fuel --json`), the fuel drawn in the tank with its centre of mass, the gauge curve for
// the current attitude, and "fill to volume" by the library's inverse gauge.
import * as api from './api.js';
import { drawGaugePlot } from './gauge_plot.js';
import { setFigure } from './panels.js';

const TABLE_STEPS = 64;

export class FuelPanel {
  constructor(state, onStatus) {
    this.state = state;
    this.onStatus = onStatus;
    this.seq = 0;
    this.table = null;
    const $ = (id) => document.getElementById(id);
    this.pitch = $('pitch');
    this.roll = $('roll');
    this.level = $('level');
    this.levelRange = $('level-range');
    // Sliders and number boxes mirror each other; attitude changes redo the table.
    const pair = (range, box, onChange) => {
      range.addEventListener('input', () => { box.value = range.value; onChange(); });
      box.addEventListener('change', () => { range.value = box.value; onChange(); });
    };
    pair($('pitch-range'), this.pitch, () => this.attitudeChanged());
    pair($('roll-range'), this.roll, () => this.attitudeChanged());
    pair(this.levelRange, this.level, () => this.query({ level: Number(this.level.value) }));
    $('fill-form').addEventListener('submit', (e) => {
      e.preventDefault();
      this.query({ volume: Number($('fill-volume').value) });
    });
  }

  attitude() {
    return { pitch: Number(this.pitch.value) || 0, roll: Number(this.roll.value) || 0 };
  }

  // A new mesh: table for the current attitude, then the fuel at half height.
  async reset() {
    this.table = null;
    document.getElementById('gauge-plot').replaceChildren();
    await this.attitudeChanged(0.5);
  }

  // Rebuilds the gauge table; keeps the level's position in the new range (or sets it to
  // `fraction` of it).
  async attitudeChanged(fraction) {
    const { mesh } = this.state;
    if (!mesh) return;
    const seq = ++this.seq;
    try {
      const old = this.table;
      const t = await api.getFuelTable(mesh.id, { ...this.attitude(), n: TABLE_STEPS });
      if (seq !== this.seq) return;
      this.table = t;
      const lo = t.rows[0].level, hi = t.rows[t.rows.length - 1].level;
      let f = fraction;
      if (f === undefined && old) {
        const ol = old.rows[0].level, oh = old.rows[old.rows.length - 1].level;
        f = oh > ol ? (Number(this.level.value) - ol) / (oh - ol) : 0.5;
      }
      f = Math.min(1, Math.max(0, f ?? 0.5));
      this.levelRange.min = lo;
      this.levelRange.max = hi;
      this.levelRange.step = (hi - lo) / 1000 || 'any';
      this.level.min = lo;
      this.level.max = hi;
      const level = lo + f * (hi - lo);
      this.level.value = level;
      this.levelRange.value = level;
      await this.query({ level });
    } catch (e) {
      if (seq === this.seq) this.onStatus(e.message);
    }
  }

  // One fuel query: {level} or {volume}; updates figures, drawing and plot.
  async query(target) {
    const { mesh, view } = this.state;
    if (!mesh) return;
    const seq = ++this.seq;
    document.body.dataset.fuel = 'busy';
    try {
      const f = await api.getFuel(mesh.id, { ...this.attitude(), ...target });
      if (seq !== this.seq) return;
      this.show(f);
      if (view) {
        view.setLayer('fuel', f.volume > 0 ? view.fuel(f.up, f.level) : null);
        view.setLayer('fuel-com', f.volume > 0 ? view.marker(f.center_of_mass, 0x1b7f3b) : null);
      }
      if (this.table) {
        drawGaugePlot(document.getElementById('gauge-plot'),
                      this.table.rows.map((r) => r.level), this.table.rows.map((r) => r.volume),
                      { level: f.level, volume: f.volume });
      }
      this.onStatus(null);
      document.body.dataset.fuel = 'ready';
    } catch (e) {
      if (seq === this.seq) {
        this.onStatus(e.message);
        document.body.dataset.fuel = 'error';
      }
    }
  }

  show(f) {
    if ('volume' in f && document.activeElement !== this.level) {
      this.level.value = f.level;
      this.levelRange.value = f.level;
    }
    setFigure('fuel-up', f.up);
    setFigure('fuel-level', f.level);
    setFigure('fuel-volume', f.volume);
    setFigure('fuel-fraction', f.fraction);
    setFigure('fuel-com', f.center_of_mass);
    setFigure('fuel-wetted-area', f.wetted_area);
    setFigure('fuel-surface-area', f.surface_area);
  }
}
