// View: Fig. 9, the histogram over knot types of the smallest total curvature
// of their equilibria divided by Milnor's bound 2π·bridge index, stacked by
// kind (BB knots, 2-bridge knots that are not BB, the others). A bar lists its
// knots; a knot opens its view.
import { el, svg, fmt, ready } from "./util.js";

const KINDS = [
  { key: "bb", label: "BB knots (bridge = braid index)", color: "#ff7f0e" },
  { key: "other", label: "other knots", color: "#b0c4de" },
  { key: "two", label: "2-bridge, not BB", color: "#000080" },
];

function kind(k) {
  if (k.bb) return "bb";
  return k.two_bridge ? "two" : "other";
}

export function showMilnor(main, site) {
  const knots = site.knots.filter((k) => k.milnor_ratio !== null);
  const ratios = knots.map((k) => k.milnor_ratio);
  const lo = 1.0, hi = Math.max(1.05, Math.max(...ratios, 1) * 1.02), bins = 40;
  const bin = (r) => Math.min(bins - 1, Math.max(0, Math.floor(((r - lo) / (hi - lo)) * bins)));
  const counts = Array.from({ length: bins }, () => ({ bb: [], other: [], two: [] }));
  for (const k of knots) counts[bin(k.milnor_ratio)][kind(k)].push(k);
  const W = 760, H = 340, L = { left: 44, right: 12, top: 12, bottom: 40 };
  const ymax = Math.max(1, ...counts.map((c) => c.bb.length + c.other.length + c.two.length));
  const x = (r) => L.left + ((r - lo) / (hi - lo)) * (W - L.left - L.right);
  const y = (c) => H - L.bottom - (c / ymax) * (H - L.top - L.bottom);
  const root = svg("svg", { width: W, height: H, viewBox: `0 0 ${W} ${H}`, id: "milnor" });
  const list = el("div", { id: "milnor-list" });
  const bw = (W - L.left - L.right) / bins;
  counts.forEach((c, b) => {
    let stack = 0;
    for (const kd of KINDS) {
      const ks = c[kd.key];
      if (!ks.length) continue;
      const r0 = lo + (b * (hi - lo)) / bins;
      root.append(svg("rect", { class: "bar", x: x(r0) + 0.5, y: y(stack + ks.length), width: bw - 1,
        height: y(stack) - y(stack + ks.length), fill: kd.color, dataset: { bin: b, kind: kd.key },
        onclick: () => showBin(b) }, svg("title", {}, `${ks.length} ${kd.label}: ${ks.map((k) => k.name).join(", ")}`)));
      stack += ks.length;
    }
  });
  for (let t = 0; t <= 5; t++) {
    const r = lo + ((hi - lo) * t) / 5;
    root.append(svg("text", { x: x(r), y: H - L.bottom + 16, "text-anchor": "middle" }, fmt(r, 3)));
  }
  for (let t = 0; t <= 4; t++) {
    const c = Math.round((ymax * t) / 4);
    root.append(svg("text", { x: L.left - 6, y: y(c) + 4, "text-anchor": "end" }, String(c)));
  }
  root.append(svg("line", { x1: x(1), x2: x(1), y1: L.top, y2: H - L.bottom, stroke: "#000", "stroke-dasharray": "4 3" }),
    svg("text", { x: (W + L.left) / 2, y: H - 6, "text-anchor": "middle" }, "smallest total curvature / (2π · bridge index)"));
  function showBin(b) {
    const r0 = lo + (b * (hi - lo)) / bins, r1 = r0 + (hi - lo) / bins;
    const ks = KINDS.flatMap((kd) => counts[b][kd.key].map((k) => ({ k, kd })));
    list.replaceChildren(el("h3", {}, `ratio ${fmt(r0, 4)} – ${fmt(r1, 4)}: ${ks.length} knot types`),
      el("ul", { class: "knot-list" }, ks.map(({ k, kd }) => el("li", {},
        el("span", { class: "swatch", style: `background:${kd.color}` }),
        el("a", { href: `#/knot/${encodeURIComponent(k.name)}`, dataset: { knot: k.name } }, k.name), ` ${fmt(k.milnor_ratio, 5)}`))));
  }
  main.append(el("h2", {}, "Milnor's bound (paper Fig. 9)"),
    el("p", { class: "muted" }, `${knots.length} knot types; total curvature > 2π·bridge index for every knot (Milnor). ` +
      `${site.knots.length - knots.length} without a stored equilibrium or a known bridge index are not shown. Click a bar to list its knots.`),
    el("div", { class: "controls" }, KINDS.map((kd) => el("span", {}, el("span", { class: "swatch", style: `background:${kd.color}` }), kd.label))),
    el("div", { class: "panel" }, root), list);
  ready("milnor");
  return null;
}
