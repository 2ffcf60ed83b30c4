// A knot's distinct states at a glance (the look of the paper's Fig. 2): one
// small picture per cluster at the cut, sorted by energy, each its
// lowest-energy member drawn as a tube of the wire's radius seen along the
// curve's axis of least extent (the smallest principal axis), segments drawn
// back to front with an outline so that over- and under-crossings read.
// A picture opens the state's 3D view.
import { curve, componentSizes } from "./data.js";
import { el, fmt } from "./util.js";

const SIZE = 112;       // [px] picture edge
const MAX_SHOWN = 40;   // [1] pictures per row; the rest are counted

/** The principal axes of points p (n*3), most extent first (power iteration on the 3×3 covariance). */
function principalAxes(p) {
  const n = p.length / 3;
  const c = [0, 0, 0];
  for (let i = 0; i < n; i++) for (let d = 0; d < 3; d++) c[d] += p[3 * i + d] / n;
  const C = [[0, 0, 0], [0, 0, 0], [0, 0, 0]];
  for (let i = 0; i < n; i++)
    for (let a = 0; a < 3; a++)
      for (let b = 0; b < 3; b++) C[a][b] += (p[3 * i + a] - c[a]) * (p[3 * i + b] - c[b]);
  const axes = [];
  for (let k = 0; k < 2; k++) {
    let v = k === 0 ? [1, 0.3, 0.1] : [0.2, 1, 0.4];
    for (let it = 0; it < 60; it++) {
      for (const u of axes) { const d = u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; v = v.map((x, j) => x - d * u[j]); }
      const w = [0, 1, 2].map((a) => C[a][0] * v[0] + C[a][1] * v[1] + C[a][2] * v[2]);
      const len = Math.hypot(...w) || 1;
      v = w.map((x) => x / len);
    }
    axes.push(v);
  }
  const [u, v] = axes;
  axes.push([u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]);
  return { centre: c, axes };
}

/** The segments [i, j] of closed components of these sizes (vertex counts), in order. */
function segments(sizes) {
  const out = [];
  let start = 0;
  for (const m of sizes) {
    for (let i = 0; i < m; i++) out.push([start + i, start + (i + 1) % m]);
    start += m;
  }
  return out;
}

/** Draws curve p (n*3; closed components of `sizes` vertices) as a tube of radius r into a SIZE×SIZE canvas. */
export function drawTube(canvas, p, r, sizes = [p.length / 3]) {
  const { centre, axes } = principalAxes(p);
  const n = p.length / 3;
  const q = [];
  for (let i = 0; i < n; i++) {
    const d = [0, 1, 2].map((j) => p[3 * i + j] - centre[j]);
    q.push(axes.map((a) => a[0] * d[0] + a[1] * d[1] + a[2] * d[2]));
  }
  const extent = Math.max(...q.map(([x, y]) => Math.max(Math.abs(x), Math.abs(y)))) + r;
  const s = (SIZE / 2 - 2) / extent;
  const depth = q.map((x) => x[2]);
  const lo = Math.min(...depth), hi = Math.max(...depth);
  const mid = ([i, j]) => depth[i] + depth[j];
  const order = segments(sizes).sort((x, y) => mid(x) - mid(y));  // back to front
  const g = canvas.getContext("2d");
  g.clearRect(0, 0, SIZE, SIZE);
  const at = (i) => [SIZE / 2 + s * q[i][0], SIZE / 2 - s * q[i][1]];
  for (const [i, j] of order) {
    const [a, b] = [at(i), at(j)];
    const t = hi > lo ? (depth[i] - lo) / (hi - lo) : 1;  // 0 far, 1 near
    // the outline with butt ends (it must not cut across the segment drawn
    // before), the fill with round ends (they close the joints)
    for (const [w, colour, cap] of [[2 * r * s + 2, "#1b2a3a", "butt"], [2 * r * s - 0.5, `hsl(205, 55%, ${38 + 30 * t}%)`, "round"]]) {
      g.lineCap = cap;
      g.strokeStyle = colour;
      g.lineWidth = Math.max(w, 1);
      g.beginPath();
      g.moveTo(...a);
      g.lineTo(...b);
      g.stroke();
    }
  }
}

/**
 * The row of state pictures: `clusters` as from clustersAtCut (by energy),
 * `energy(i)`, `open(i)`. Returns {node, render(clusters)}.
 */
export function stateGallery(k, radius, energy, open) {
  const node = el("div", { class: "gallery", id: "state-gallery" });
  function render(clusters) {
    node.replaceChildren();
    const shown = clusters.clusters.slice(0, MAX_SHOWN);
    const e0 = shown.length ? shown[0].energyMin : 0;
    shown.forEach((c, rank) => {
      const canvas = el("canvas", { width: SIZE, height: SIZE });
      drawTube(canvas, curve(k, c.representative), radius, componentSizes(k));
      node.append(el("figure", {
        class: "state", dataset: { index: c.representative, rank }, title: `state ${rank}: open in 3D`,
        onclick: () => open(c.representative),
      }, canvas, el("figcaption", {}, `${rank}: E ${fmt(energy(c.representative))}` +
        (rank ? ` (+${fmt(100 * (c.energyMin / e0 - 1))}%)` : ""))));
    });
    if (clusters.count > shown.length)
      node.append(el("p", { class: "muted" }, `and ${clusters.count - shown.length} more states (in the table below)`));
  }
  return { node, render };
}
