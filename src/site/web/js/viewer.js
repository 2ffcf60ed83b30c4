// A 3D view of one equilibrium: the wire as a lit tube of its radius (times a
// thickness factor), vertex-coloured, in a three.js scene with orbit controls
// (drag: rotate, wheel: zoom, right-drag: pan). It first looks along the
// curve's smallest principal axis, as the figures' "top" view.
import * as THREE from "../three/build/three.module.js";
import { OrbitControls } from "../three/examples/jsm/controls/OrbitControls.js";

const SIDES = 14;

/** Eigenvector of the smallest eigenvalue of a symmetric 3 by 3 matrix (Jacobi rotations). */
function smallestAxis(A) {
  const a = A.map((r) => [...r]);
  const V = [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  for (let sweep = 0; sweep < 30; sweep++) {
    for (const [p, q] of [[0, 1], [0, 2], [1, 2]]) {
      if (Math.abs(a[p][q]) < 1e-15) continue;
      const theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
      const t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
      const c = 1 / Math.sqrt(t * t + 1), s = t * c;
      for (let k = 0; k < 3; k++) {
        const akp = a[k][p], akq = a[k][q];
        a[k][p] = c * akp - s * akq; a[k][q] = s * akp + c * akq;
      }
      for (let k = 0; k < 3; k++) {
        const apk = a[p][k], aqk = a[q][k];
        a[p][k] = c * apk - s * aqk; a[q][k] = s * apk + c * aqk;
      }
      for (let k = 0; k < 3; k++) {
        const vkp = V[k][p], vkq = V[k][q];
        V[k][p] = c * vkp - s * vkq; V[k][q] = s * vkp + c * vkq;
      }
    }
  }
  const j = [0, 1, 2].reduce((best, i) => (a[i][i] < a[best][best] ? i : best), 0);
  return new THREE.Vector3(V[0][j], V[1][j], V[2][j]).normalize();
}

/**
 * The tube around the closed polygon `points` (Float32Array n*3) as an
 * indexed BufferGeometry: a ring of SIDES vertices at every polygon vertex,
 * in the plane normal to the mean of its two edge directions, oriented by a
 * parallel-transported frame whose closing twist is spread evenly along the
 * curve; `colors` (n*3, sRGB in [0, 1]) per polygon vertex.
 */
export function tubeGeometry(points, radius, colors, components = [points.length / 3]) {
  if (components.length > 1) return mergedTubes(points, radius, colors, components);
  const n = points.length / 3;
  const P = (i) => new THREE.Vector3(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
  const T = [];
  for (let i = 0; i < n; i++) {
    const a = P(i).sub(P((i + n - 1) % n)).normalize(), b = P((i + 1) % n).sub(P(i)).normalize();
    const t = a.add(b);
    T.push(t.lengthSq() > 1e-12 ? t.normalize() : b);
  }
  const N = [];
  let seed = Math.abs(T[0].x) < 0.9 ? new THREE.Vector3(1, 0, 0) : new THREE.Vector3(0, 1, 0);
  N.push(seed.sub(T[0].clone().multiplyScalar(seed.dot(T[0]))).normalize());
  for (let i = 1; i < n; i++) {
    const v = N[i - 1].clone().sub(T[i].clone().multiplyScalar(N[i - 1].dot(T[i])));
    N.push(v.lengthSq() > 1e-12 ? v.normalize() : N[i - 1].clone());
  }
  const end = N[n - 1].clone().sub(T[0].clone().multiplyScalar(N[n - 1].dot(T[0]))).normalize();
  const twist = Math.atan2(new THREE.Vector3().crossVectors(N[0], end).dot(T[0]), N[0].dot(end));
  const pos = new Float32Array(n * SIDES * 3), nor = new Float32Array(n * SIDES * 3), col = new Float32Array(n * SIDES * 3);
  for (let i = 0; i < n; i++) {
    const normal = N[i].clone().applyAxisAngle(T[i], (-twist * i) / n);
    const binormal = new THREE.Vector3().crossVectors(T[i], normal);
    const c = P(i);
    for (let s = 0; s < SIDES; s++) {
      const phi = (2 * Math.PI * s) / SIDES;
      const d = normal.clone().multiplyScalar(Math.cos(phi)).add(binormal.clone().multiplyScalar(Math.sin(phi)));
      const o = 3 * (i * SIDES + s);
      pos.set([c.x + radius * d.x, c.y + radius * d.y, c.z + radius * d.z], o);
      nor.set([d.x, d.y, d.z], o);
      col.set([colors[3 * i], colors[3 * i + 1], colors[3 * i + 2]], o);
    }
  }
  const index = new Uint32Array(n * SIDES * 6);
  let q = 0;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    for (let s = 0; s < SIDES; s++) {
      const s1 = (s + 1) % SIDES;
      const a = i * SIDES + s, b = j * SIDES + s, c = j * SIDES + s1, d = i * SIDES + s1;
      index.set([a, b, c, a, c, d], q);
      q += 6;
    }
  }
  return indexedGeometry(pos, nor, col, index);
}

/** An indexed BufferGeometry of positions, normals and colours (3 floats per vertex). */
function indexedGeometry(pos, nor, col, index) {
  const g = new THREE.BufferGeometry();
  g.setAttribute("position", new THREE.BufferAttribute(pos, 3));
  g.setAttribute("normal", new THREE.BufferAttribute(nor, 3));
  g.setAttribute("color", new THREE.BufferAttribute(col, 3));
  g.setIndex(new THREE.BufferAttribute(index, 1));
  return g;
}

/** One closed tube per component (vertex counts `components`, back to back) in one geometry. */
function mergedTubes(points, radius, colors, components) {
  const parts = [];
  let start = 0;
  for (const n of components) {
    parts.push(tubeGeometry(points.subarray(3 * start, 3 * (start + n)), radius, colors.subarray(3 * start, 3 * (start + n))));
    start += n;
  }
  const total = parts.reduce((s, g) => s + g.getAttribute("position").count, 0);
  const pos = new Float32Array(3 * total), nor = new Float32Array(3 * total), col = new Float32Array(3 * total);
  const index = new Uint32Array(parts.reduce((s, g) => s + g.getIndex().count, 0));
  let v = 0, q = 0;
  for (const g of parts) {
    pos.set(g.getAttribute("position").array, 3 * v);
    nor.set(g.getAttribute("normal").array, 3 * v);
    col.set(g.getAttribute("color").array, 3 * v);
    const idx = g.getIndex().array;
    for (let i = 0; i < idx.length; i++) index[q + i] = idx[i] + v;
    v += g.getAttribute("position").count;
    q += idx.length;
    g.dispose();
  }
  return indexedGeometry(pos, nor, col, index);
}

export class TubeViewer {
  constructor(container, { width = 520, height = 520 } = {}) {
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setSize(width, height);
    this.renderer.setClearColor(0xffffff, 1);
    this.renderer.domElement.classList.add("viewer-canvas");
    container.append(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.camera = new THREE.PerspectiveCamera(30, width / height, 0.1, 1e5);
    this.scene.add(new THREE.AmbientLight(0xffffff, 0.58));
    const key = new THREE.DirectionalLight(0xffffff, 0.55);
    key.position.set(-1, 1.5, 2);
    const fill = new THREE.DirectionalLight(0xffffff, 0.22);
    fill.position.set(1.5, -0.5, 1);
    this.camera.add(key, fill);  // lights move with the camera
    this.scene.add(this.camera);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener("change", () => this.render());
    this.mesh = null;
  }

  /** Shows the curve (Float32Array n*3) as a tube, one per component of a
   *  link (`components`: vertex counts); the camera is reset unless keepCamera. */
  show(points, colors, radius, { keepCamera = false, components } = {}) {
    const n = points.length / 3;
    const center = new THREE.Vector3();
    for (let i = 0; i < n; i++) center.add(new THREE.Vector3(points[3 * i], points[3 * i + 1], points[3 * i + 2]));
    center.divideScalar(n);
    const C = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
    let extent = 0;
    for (let i = 0; i < n; i++) {
      const p = [points[3 * i] - center.x, points[3 * i + 1] - center.y, points[3 * i + 2] - center.z];
      extent = Math.max(extent, Math.hypot(...p));
      for (let r = 0; r < 3; r++) for (let c = 0; c < 3; c++) C[r][c] += p[r] * p[c];
    }
    if (this.mesh) { this.scene.remove(this.mesh); this.mesh.geometry.dispose(); this.mesh.material.dispose(); }
    this.geometry = tubeGeometry(points, radius, colors, components);  // in the data's coordinates (for the OBJ download)
    const material = new THREE.MeshPhongMaterial({ vertexColors: THREE.VertexColors, shininess: 50, specular: 0x2a2a2a });
    this.mesh = new THREE.Mesh(this.geometry, material);
    this.mesh.position.copy(center).negate();
    this.scene.add(this.mesh);
    if (!keepCamera) {
      const axis = smallestAxis(C);
      const distance = (1.08 * (extent + radius)) / Math.sin((this.camera.fov * Math.PI) / 360);
      this.camera.position.copy(axis.multiplyScalar(distance));
      this.camera.up.set(0, 1, 0);
      if (Math.abs(this.camera.position.clone().normalize().y) > 0.99) this.camera.up.set(1, 0, 0);
      this.camera.near = distance / 100;
      this.camera.far = distance * 10;
      this.camera.updateProjectionMatrix();
      this.controls.target.set(0, 0, 0);
      this.controls.update();
    }
    this.render();
  }

  render() { this.renderer.render(this.scene, this.camera); }

  dispose() {
    this.controls.dispose();
    if (this.mesh) { this.mesh.geometry.dispose(); this.mesh.material.dispose(); }
    this.renderer.dispose();
    this.renderer.forceContextLoss();
  }
}
