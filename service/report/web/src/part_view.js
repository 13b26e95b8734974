// The part in 3D (three.js): every triangle in the colour of its face's class (the setup
// that reaches it, unreachable, neutral), feature borders as lines, orbit/zoom/pan,
// picking a face, and the camera turned to look along a setup direction.
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";

// Colours pass through unchanged (no sRGB conversion, no tone mapping), so a lit pixel is
// its class colour times the light: the browser test can tell the setups apart by hue.
THREE.ColorManagement.enabled = false;

// three.js lights are physical (a Lambert surface reflects intensity/pi), so pi times
// these fractions makes a face turned to the camera exactly its class colour.
const kAmbient = 0.45 * Math.PI;
const kHeadlight = 0.55 * Math.PI;

function hexToRgb(hex) {
  const v = parseInt(hex.slice(1), 16);
  return [((v >> 16) & 255) / 255, ((v >> 8) & 255) / 255, (v & 255) / 255];
}

// Edges between triangles of different surfaces (or classes): the features' outlines.
function borderEdges(mesh) {
  const { triangles, triangleFace, faceSurface, positions } = mesh;
  const seen = new Map();
  const out = [];
  const nv = positions.length / 3;
  const owner = (t) => faceSurface[triangleFace[t]];
  for (let t = 0; t < triangles.length / 3; ++t) {
    for (let i = 0; i < 3; ++i) {
      const a = triangles[3 * t + i], b = triangles[3 * t + ((i + 1) % 3)];
      const key = Math.min(a, b) * nv + Math.max(a, b);
      const other = seen.get(key);
      if (other === undefined) {
        seen.set(key, t);
      } else if (owner(other) !== owner(t)) {
        out.push(a, b);
      }
    }
  }
  const lines = new Float32Array(out.length * 3);
  for (let i = 0; i < out.length; ++i) lines.set(positions.subarray(3 * out[i], 3 * out[i] + 3), 3 * i);
  return lines;
}

export class PartView {
  constructor(container, data, onPick) {
    this.data = data;
    this.mesh = data.mesh;
    this.onPick = onPick;
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: true });
    this.renderer.outputColorSpace = THREE.LinearSRGBColorSpace;
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(0xffffff, 1);
    container.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.buildGeometry();
    this.buildCamera();
    this.listen();
    this.highlight(null);
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
  }

  buildGeometry() {
    const { positions, triangles } = this.mesh;
    const n = triangles.length;
    const flat = new Float32Array(n * 3);
    for (let i = 0; i < n; ++i) flat.set(positions.subarray(3 * triangles[i], 3 * triangles[i] + 3), 3 * i);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute("position", new THREE.BufferAttribute(flat, 3));
    geometry.setAttribute("color", new THREE.BufferAttribute(new Float32Array(n * 3), 3));
    geometry.computeVertexNormals();
    geometry.computeBoundingSphere();
    this.geometry = geometry;
    const material = new THREE.MeshLambertMaterial({ vertexColors: true, polygonOffset: true,
      polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
    this.part = new THREE.Mesh(geometry, material);
    this.scene.add(this.part);
    const edges = new THREE.BufferGeometry();
    edges.setAttribute("position", new THREE.BufferAttribute(borderEdges(this.mesh), 3));
    this.scene.add(new THREE.LineSegments(edges, new THREE.LineBasicMaterial({ color: 0x333333 })));
    this.scene.add(new THREE.AmbientLight(0xffffff, kAmbient));
  }

  buildCamera() {
    const sphere = this.geometry.boundingSphere;
    this.center = sphere.center.clone();
    this.radius = sphere.radius || 1;
    this.camera = new THREE.PerspectiveCamera(30, 1, this.radius / 100, this.radius * 100);
    const light = new THREE.DirectionalLight(0xffffff, kHeadlight);
    // A headlight: light and target both ride with the camera.
    light.position.set(0, 0, 0);
    light.target.position.set(0, 0, -1);
    this.camera.add(light, light.target);
    this.scene.add(this.camera);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.target.copy(this.center);
    this.controls.addEventListener("change", () => this.render());
    this.viewAlong([1, -1.4, 1.1]);
  }

  // The camera on the side of `u` (the side rays leave the surfaces to), looking back at
  // the part: what the tool coming along -u sees.
  viewAlong(u) {
    const d = new THREE.Vector3(u[0], u[1], u[2]).normalize();
    const distance = this.radius / Math.sin((this.camera.fov * Math.PI) / 360) * 1.08;
    const up = Math.abs(d.z) > 0.99 ? new THREE.Vector3(0, 1, 0) : new THREE.Vector3(0, 0, 1);
    this.camera.up.copy(up);
    this.camera.position.copy(this.center).addScaledVector(d, distance);
    this.camera.lookAt(this.center);
    this.controls.update();
    this.render();
  }

  // Colours every triangle by its face's class; with a selection, the selected classes
  // (a set of class indices) keep their colour and the rest fade.
  highlight(selectedClasses, selectedSurface = null) {
    const colors = this.geometry.getAttribute("color");
    const classes = this.data.classes.map((c) => hexToRgb(c.color));
    const faded = this.data.classes.map((c) => hexToRgb(c.faded));
    const { triangleFace, faceClass, faceSurface } = this.mesh;
    for (let t = 0; t < triangleFace.length; ++t) {
      const face = triangleFace[t];
      const cls = faceClass[face];
      const on = (!selectedClasses || selectedClasses.has(cls)) &&
        (selectedSurface === null || faceSurface[face] === selectedSurface);
      const rgb = on ? classes[cls] : faded[cls];
      for (let k = 0; k < 3; ++k) colors.setXYZ(3 * t + k, rgb[0], rgb[1], rgb[2]);
    }
    colors.needsUpdate = true;
    this.render();
  }

  listen() {
    const canvas = this.renderer.domElement;
    let down = null;
    canvas.addEventListener("pointerdown", (e) => (down = [e.clientX, e.clientY]));
    canvas.addEventListener("pointerup", (e) => {
      if (down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) < 4) this.onPick(this.pick(e), true);
      down = null;
    });
    let pending = null;
    canvas.addEventListener("pointermove", (e) => {
      if (e.buttons || pending) return;
      pending = requestAnimationFrame(() => {
        pending = null;
        this.onPick(this.pick(e), false);
      });
    });
  }

  // The input face under the pointer, or null.
  pick(event) {
    const rect = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1,
      -((event.clientY - rect.top) / rect.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, this.camera);
    const hit = ray.intersectObject(this.part, false)[0];
    return hit ? this.mesh.triangleFace[hit.faceIndex] : null;
  }

  resize() {
    const w = this.container.clientWidth || 1, h = this.container.clientHeight || 1;
    this.renderer.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.render();
  }

  render() {
    if (this.camera) this.renderer.render(this.scene, this.camera);
  }
}
