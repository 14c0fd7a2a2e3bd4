// The 3-D view: one mesh, markers (points) and arrows, orbit controls. Z is up. Everything is drawn
// relative to the mesh's drawing origin (the server sends float32 positions relative to it).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

export class View {
  constructor(container) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true,
                                               stencil: true });
    this.renderer.setPixelRatio(window.devicePixelRatio);
    this.renderer.setClearColor(0xf3f5f9);
    this.renderer.localClippingEnabled = true;  // the fuel is the tank clipped by its plane
    container.appendChild(this.renderer.domElement);

    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
    this.camera.up.set(0, 0, 1);
    this.camera.position.set(3, -4, 2.5);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.render());

    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.5);
    sun.position.set(2, -3, 5);
    this.camera.add(sun);
    this.scene.add(this.camera);

    this.origin = new THREE.Vector3();  // the drawing origin, in model coordinates
    this.size = 1;
    this.groups = {};  // named layers that can be replaced: 'mesh', 'com', 'axes', ...

    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth);
    const h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render() {
    this.renderer.render(this.scene, this.camera);
  }

  // Replaces the named layer (removing it when object is null) and redraws.
  setLayer(name, object) {
    const old = this.groups[name];
    if (old) {
      this.scene.remove(old);
      old.traverse((o) => {
        if (o.geometry) o.geometry.dispose();
        if (o.material) o.material.dispose();
      });
    }
    this.groups[name] = object;
    if (object) this.scene.add(object);
    this.render();
  }

  // Model coordinates [x,y,z] -> the scene's (relative to the drawing origin).
  toScene(p) {
    return new THREE.Vector3(p[0], p[1], p[2]).sub(this.origin);
  }

  // Shows a new mesh; clears every other layer and frames the camera on it.
  showMesh(summary, geometry) {
    for (const name of Object.keys(this.groups)) this.setLayer(name, null);
    this.origin.fromArray(summary.drawing_origin);
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(geometry.positions, 3));
    g.setIndex(new THREE.BufferAttribute(geometry.indices, 1));
    g.computeVertexNormals();
    this.geometry = g;
    const group = new THREE.Group();
    group.add(new THREE.Mesh(g, new THREE.MeshStandardMaterial({
      color: 0x8fa6c8, metalness: 0.1, roughness: 0.7, side: THREE.FrontSide,
      transparent: true, opacity: 0.55, depthWrite: false })));
    // Back faces in another colour show inside-out or open parts.
    group.add(new THREE.Mesh(g, new THREE.MeshStandardMaterial({
      color: 0xc98f6b, side: THREE.BackSide, transparent: true, opacity: 0.35,
      depthWrite: false })));
    this.setLayer('mesh', group);

    const lo = this.toScene(summary.bounds.min), hi = this.toScene(summary.bounds.max);
    this.size = Math.max(hi.clone().sub(lo).length(), 1e-9);
    const grid = new THREE.GridHelper(this.size * 1.5, 10, 0x9aa5b8, 0xd0d6e0);
    grid.rotation.x = Math.PI / 2;  // the grid lies in the xy plane (z up)
    grid.position.z = lo.z;
    this.setLayer('grid', grid);
    const axes = new THREE.AxesHelper(this.size * 0.25);
    axes.position.copy(this.toScene([0, 0, 0]));
    this.setLayer('world-axes', axes);

    this.camera.near = this.size / 1000;
    this.camera.far = this.size * 100;
    this.camera.position.set(0.9 * this.size, -1.3 * this.size, 0.8 * this.size);
    this.controls.target.set(0, 0, 0);
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.render();
  }

  // The fuel of a closed tank below the plane up·x = level (model coordinates): the wetted wall
  // is the tank drawn clipped by the plane, the free surface a cap drawn where the clipped tank's
  // back faces outnumber its front faces (stencil parity: inside the closed surface). Nothing is
  // measured here; the figures come from the library.
  fuel(up, level) {
    const n = new THREE.Vector3(up[0], up[1], up[2]).normalize();
    // three.js keeps points with n'·p + c >= 0: n' = -up, c = level - up·origin keeps up·x <= level.
    const clip = new THREE.Plane(n.clone().negate(), level - n.dot(this.origin));
    const group = new THREE.Group();
    const wall = new THREE.MeshStandardMaterial({
      color: 0xd9a21b, side: THREE.DoubleSide, clippingPlanes: [clip], metalness: 0.0,
      roughness: 0.6, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
    group.add(new THREE.Mesh(this.geometry, wall));

    const stencilPass = (side, op) => new THREE.MeshBasicMaterial({
      side, clippingPlanes: [clip], colorWrite: false, depthWrite: false, depthTest: false,
      stencilWrite: true, stencilFunc: THREE.AlwaysStencilFunc, stencilFail: op,
      stencilZFail: op, stencilZPass: op });
    const back = new THREE.Mesh(this.geometry, stencilPass(THREE.BackSide,
                                                          THREE.IncrementWrapStencilOp));
    const front = new THREE.Mesh(this.geometry, stencilPass(THREE.FrontSide,
                                                           THREE.DecrementWrapStencilOp));
    back.renderOrder = front.renderOrder = 1;
    group.add(back, front);

    const cap = new THREE.Mesh(new THREE.PlaneGeometry(4 * this.size, 4 * this.size),
                               new THREE.MeshStandardMaterial({
                                 color: 0xf2c14e, metalness: 0.0, roughness: 0.4,
                                 side: THREE.DoubleSide, stencilWrite: true, stencilRef: 0,
                                 stencilFunc: THREE.NotEqualStencilFunc,
                                 stencilFail: THREE.ReplaceStencilOp,
                                 stencilZFail: THREE.ReplaceStencilOp,
                                 stencilZPass: THREE.ReplaceStencilOp }));
    // The cap lies in the plane, centred on the foot of the drawing origin (scene 0,0,0).
    cap.position.copy(n.clone().multiplyScalar(level - n.dot(this.origin)));
    cap.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), n);
    cap.renderOrder = 2;
    cap.onAfterRender = (renderer) => renderer.clearStencil();
    group.add(cap);
    return group;
  }

  // A sphere marker at model point p, sized relative to the mesh.
  marker(p, color) {
    const m = new THREE.Mesh(new THREE.SphereGeometry(this.size * 0.015, 16, 12),
                             new THREE.MeshBasicMaterial({ color, depthTest: false }));
    m.renderOrder = 10;
    m.position.copy(this.toScene(p));
    return m;
  }

  // Arrows from model point p along unit directions, with lengths and colours.
  arrows(p, directions, lengths, colors) {
    const group = new THREE.Group();
    directions.forEach((d, i) => {
      const a = new THREE.ArrowHelper(new THREE.Vector3(d[0], d[1], d[2]).normalize(),
                                      this.toScene(p), lengths[i], colors[i],
                                      0.15 * lengths[i], 0.07 * lengths[i]);
      group.add(a);
    });
    return group;
  }

  // Line segments between model points: pairs [[a, b], ...].
  segments(pairs, color) {
    const data = new Float32Array(pairs.length * 6);
    pairs.forEach(([a, b], i) => {
      data.set(this.toScene(a).toArray(), 6 * i);
      data.set(this.toScene(b).toArray(), 6 * i + 3);
    });
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(data, 3));
    const lines = new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color, depthTest: false }));
    lines.renderOrder = 11;
    return lines;
  }

  // Faces drawn over the mesh in one colour: polygons [[x0, y0, z0, x1, y1, z1, ...], ...], each
  // as its fan of triangles, both sides, seen through the surface in front of them.
  faces(polygons, color) {
    const triangles = [];
    for (const p of polygons) {
      const corner = (k) => this.toScene([p[3 * k], p[3 * k + 1], p[3 * k + 2]]).toArray();
      for (let k = 1; k + 1 < p.length / 3; ++k) triangles.push(...corner(0), ...corner(k), ...corner(k + 1));
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(triangles), 3));
    const mesh = new THREE.Mesh(g, new THREE.MeshBasicMaterial({
      color, side: THREE.DoubleSide, depthTest: false, transparent: true, opacity: 0.6 }));
    mesh.renderOrder = 10;
    return mesh;
  }
}

// True when this browser can draw WebGL.
export function webglAvailable() {
  try {
    const c = document.createElement('canvas');
    return !!(c.getContext('webgl2') || c.getContext('webgl'));
  } catch {
    return false;
  }
}
