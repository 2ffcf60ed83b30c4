// The complete-linkage dendrogram of a knot (paper Fig. 6, middle) from the
// stored linkage, leaves in the stored leaf order, with the cut drawn as a
// line; merges below the cut take their cluster's colour. Clicking the plot
// moves the cut to that height.
import { svg, fmt, clusterColor } from "./util.js";

/** {node, setCut(cut, rank)}; onPick(height) when the plot is clicked. */
export function dendrogramPlot(k, { onPick, width = 560, height = 320 }) {
  const m = k.equilibria, L = { left: 44, right: 10, top: 12, bottom: 22 };
  const top = Math.max(0.05, ...k.linkage.map((r) => r[2] ?? 0)) * 1.05;
  const pos = new Map(k.leaf_order.map((leaf, p) => [leaf, p]));
  const x = (p) => L.left + ((p + 0.5) / Math.max(m, 1)) * (width - L.left - L.right);
  const y = (h) => height - L.bottom - (h / top) * (height - L.top - L.bottom);
  const root = svg("svg", { width, height, viewBox: `0 0 ${width} ${height}`, id: "dendrogram" });
  for (let t = 0; t <= 4; t++) {
    const h = (top * t) / 4;
    root.append(svg("line", { x1: L.left - 4, x2: L.left, y1: y(h), y2: y(h), stroke: "#667085" }),
      svg("text", { x: L.left - 6, y: y(h) + 4, "text-anchor": "end" }, fmt(h, 2)));
  }
  root.append(svg("text", { x: L.left, y: height - 4 }, "equilibria in dendrogram order; height: 1 − similarity"));
  const xpos = new Float64Array(m + Math.max(m - 1, 0)), hpos = new Float64Array(xpos.length), leaf = new Int32Array(xpos.length);
  for (let i = 0; i < m; i++) { xpos[i] = x(pos.get(i)); leaf[i] = i; }
  const paths = k.linkage.map(([a, b, h], j) => {
    const node = m + j;
    xpos[node] = (xpos[a] + xpos[b]) / 2;
    hpos[node] = h;
    leaf[node] = leaf[a];
    const p = svg("path", { d: `M${xpos[a]},${y(hpos[a])}V${y(h)}H${xpos[b]}V${y(hpos[b])}`, fill: "none", "stroke-width": 1.2 });
    root.append(p);
    return { p, h, leaf: leaf[a] };
  });
  const cutLine = svg("line", { x1: L.left, x2: width - L.right, stroke: "#d62728", "stroke-dasharray": "5 3", "stroke-width": 1.5 });
  root.append(cutLine);
  root.addEventListener("click", (e) => {
    const r = root.getBoundingClientRect();
    const h = ((height - L.bottom - (e.clientY - r.top)) / (height - L.top - L.bottom)) * top;
    if (h >= 0 && h <= 1) onPick(Math.round(h * 2000) / 2000);
  });
  function setCut(cut, rank) {
    cutLine.setAttribute("y1", y(Math.min(cut, top)));
    cutLine.setAttribute("y2", y(Math.min(cut, top)));
    for (const { p, h, leaf: l } of paths) p.setAttribute("stroke", h <= cut ? clusterColor(rank[l]) : "#555");
  }
  return { node: root, setCut };
}
