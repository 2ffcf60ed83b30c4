// The MDS map of a knot (paper Fig. 6, left): one point per equilibrium at
// its classical-MDS coordinates of 1 − similarity (computed by knots site),
// coloured by cluster; clicking a point opens the equilibrium in 3D.
import { svg, fmt, clusterColor } from "./util.js";

/** {node, color(rank, representatives)}; energy(i) for the tooltips. */
export function mdsPlot(k, { onClick, energy, size = 420 }) {
  const pad = 24;
  const xs = k.mds.map((p) => p[0] ?? 0), ys = k.mds.map((p) => p[1] ?? 0);
  const span = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys), 1e-9);
  const cx = (Math.max(...xs) + Math.min(...xs)) / 2, cy = (Math.max(...ys) + Math.min(...ys)) / 2;
  const sx = (x) => size / 2 + ((x - cx) / span) * (size - 2 * pad);
  const sy = (y) => size / 2 - ((y - cy) / span) * (size - 2 * pad);
  const root = svg("svg", { width: size, height: size, viewBox: `0 0 ${size} ${size}`, class: "mds", id: "mds" });
  root.append(svg("rect", { x: 0.5, y: 0.5, width: size - 1, height: size - 1, fill: "none", stroke: "#d8dce5" }));
  const points = k.mds.map((p, i) => {
    const c = svg("circle", { cx: sx(p[0] ?? 0), cy: sy(p[1] ?? 0), r: 5, class: "point", dataset: { index: i },
      onclick: () => onClick(i) },
    svg("title", {}, `equilibrium ${i}, energy ${fmt(energy(i), 6)}`));
    root.append(c);
    return c;
  });
  root.append(svg("text", { x: 8, y: size - 8, class: "muted" },
    `MDS of 1 − similarity (${fmt(100 * (k.mds_explained ?? 0), 3)}% of the spread)`));
  function color(rank, representatives) {
    points.forEach((c, i) => {
      c.setAttribute("fill", clusterColor(rank[i]));
      c.setAttribute("r", representatives.has(i) ? 7 : 5);
    });
  }
  return { node: root, color };
}
