// The viewer page: opens meshes (bundled list, file picker, drag and drop), draws them and fills
// the panels from the server's API.
import * as api from './api.js';
import { View, webglAvailable } from './scene.js';
import { FuelPanel } from './fuel_panel.js';
import { fillMeshPanel, showMessage, clearFigures } from './panels.js';
import { PropsPanel } from './props_panel.js';

const state = { info: null, mesh: null, view: null };

// A panel's own status line: null clears it, text shows it as a problem of that panel.
function panelStatus(id) {
  return (text) => {
    const el = document.getElementById(id);
    el.textContent = text || '';
    el.classList.toggle('problem', !!text);
  };
}
const props = new PropsPanel(state, panelStatus('props-status'), async (summary, text) => {
  document.getElementById('mesh-select').value = '';
  await openMesh(async () => summary);
  showMessage(text, 'info');
});
const fuel = new FuelPanel(state, panelStatus('fuel-status'));

function setState(s) {
  document.body.dataset.state = s;
}

async function openMesh(load) {
  setState('loading');
  try {
    const summary = await load();
    const geometry = await api.getGeometry(summary.id);
    state.mesh = summary;
    document.body.dataset.meshId = summary.id;
    showMessage(null);
    clearFigures(document.getElementById('side'));
    fillMeshPanel(summary);
    if (state.view) state.view.showMesh(summary, geometry);
    const work = [];
    if (state.info.features.props) work.push(props.update());
    if (state.info.features.fuel) work.push(fuel.reset());
    await Promise.all(work);
    setState('ready');
  } catch (e) {
    showMessage(e.message);
    setState('error');
  }
}

async function openFile(file) {
  const cap = state.info ? state.info.max_upload : Infinity;
  if (file.size > cap) {
    showMessage(`${file.name}: ${file.size} bytes is over the server's upload limit of ${cap} ` +
                'bytes (pgamesh serve --max-upload)');
    setState('error');
    return;
  }
  if (file.size === 0) {
    showMessage(`${file.name}: the file is empty`);
    setState('error');
    return;
  }
  document.getElementById('mesh-select').value = '';
  await openMesh(() => api.upload(file));
}

function wireInputs() {
  const input = document.getElementById('file-input');
  input.addEventListener('change', () => {
    if (input.files.length) openFile(input.files[0]);
    input.value = '';
  });

  const select = document.getElementById('mesh-select');
  select.addEventListener('change', () => {
    if (select.value) openMesh(() => api.getMesh(select.value));
  });

  const view = document.getElementById('view');
  const overlay = document.getElementById('drop-overlay');
  const dragging = (on) => {
    view.classList.toggle('dragging', on);
    overlay.hidden = !on;
  };
  view.addEventListener('dragover', (e) => {
    e.preventDefault();
    e.dataTransfer.dropEffect = 'copy';
    dragging(true);
  });
  view.addEventListener('dragleave', () => dragging(false));
  view.addEventListener('drop', (e) => {
    e.preventDefault();
    dragging(false);
    if (e.dataTransfer.files.length) openFile(e.dataTransfer.files[0]);
  });
}

async function start() {
  wireInputs();
  if (webglAvailable()) {
    state.view = new View(document.getElementById('view'));
  } else {
    showMessage('This browser cannot draw WebGL: the figures are shown, the 3-D view is not.',
                'info');
  }
  try {
    state.info = await api.getInfo();
    const { features } = state.info;
    document.getElementById('props-body').hidden = !features.props;
    document.getElementById('fuel-body').hidden = !features.fuel;
    if (!features.props)
      document.getElementById('props-status').textContent =
        'Not available: this server was built without mass properties.';
    if (!features.fuel)
      document.getElementById('fuel-status').textContent =
        'Not available: this server was built without fuel gauging.';
    const meshes = await api.listMeshes();
    const select = document.getElementById('mesh-select');
    const none = new Option('—', '');
    select.replaceChildren(none, ...meshes.map((m) => new Option(m.name, m.id)));
    const first = meshes.find((m) => m.origin === 'command line') ||
                  meshes.find((m) => m.name === 'tank.obj') || meshes[0];
    if (first) {
      select.value = first.id;
      await openMesh(() => api.getMesh(first.id));
    } else {
      setState('ready');
    }
  } catch (e) {
    showMessage(`The server did not answer: ${e.message}`);
    setState('error');
  }
}

start();
window.pgameshViewer = state;  // for the tests and the console
