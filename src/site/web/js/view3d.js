// View: one equilibrium in 3D, or two of the same knot side by side with
// their similarity. Colour by curvature (a shared scale and colour bar) or by
// contact; the wire's thickness as stored (its radius r) or thicker; OBJ
// downloads of the curve and of the tube.
import { loadKnot, knotAttribute, curve, attributeNames, componentSizes, fromLedger } from "./data.js";
import { clustersAtCut } from "./clusters.js";
import { TubeViewer } from "./viewer.js";
import { viridis, viridisGradient, percentile, CONTACT, FREE } from "./colormap.js";
import { curveObj, meshObj, download } from "./obj.js";
import { el, fmt, clusterColor, ATTRIBUTE_LABELS, ready } from "./util.js";

const settings = { mode: "curvature", thickness: 1 };  // kept while navigating

/** sRGB in [0, 1] of a CSS colour "#rrggbb" or "rgb(r,g,b)". */
function rgb(css) {
  const h = /^#([0-9a-f]{2})([0-9a-f]{2})([0-9a-f]{2})$/i.exec(css);
  if (h) return [1, 2, 3].map((j) => parseInt(h[j], 16) / 255);
  return css.match(/[\d.]+/g).slice(0, 3).map((x) => Number(x) / 255);
}

function colors(k, i, mode, vmax) {
  const n = k.vertices, out = new Float32Array(3 * n);
  let start = 0, component = 0;
  for (const size of componentSizes(k)) {
    for (let u = 0; u < size; u++) {
      const v = start + u, previous = start + ((u + size - 1) % size);
      let c;
      if (mode === "contact") c = k.contact[i * n + v] || k.contact[i * n + previous] ? CONTACT : FREE;
      else if (mode === "component") c = rgb(clusterColor(component));
      else c = viridis(k.curvature[i * n + v] / vmax);
      out.set(c, 3 * v);
    }
    start += size;
    component += 1;
  }
  return out;
}

export async function showEquilibria(main, site, name, indices) {
  const rec = site.byName.get(name);
  if (!rec) throw new Error(`no knot ${name} in this data set`);
  const k = await loadKnot(site, name);
  const m = k.equilibria;
  if (!indices.length || indices.length > 2 || !indices.every((i) => Number.isInteger(i) && i >= 0 && i < m))
    throw new Error(`${name} has equilibria 0 .. ${m - 1}; the address names ${indices.join(", ") || "none"}`);
  const value = (i, a) => knotAttribute(site, k, i, a);
  const cut = k.cut ?? site.cut;
  const clusters = clustersAtCut(k.linkage, m, cut, (i) => value(i, "energy"));
  const components = componentSizes(k);
  if (components.length > 1 && !showEquilibria.linkSeen) {
    settings.mode = "component";  // a link opens with one colour per component
    showEquilibria.linkSeen = true;
  }
  const radius = site.dataset.radius;
  let curvatures = [];
  for (const i of indices) curvatures = curvatures.concat(Array.from(k.curvature.subarray(i * k.vertices, (i + 1) * k.vertices)));
  const vmax = Math.max(percentile(curvatures, 99), 1e-9);

  const back = el("a", { href: `#/knot/${encodeURIComponent(name)}` }, `← ${name}`);
  const mode = el("select", { id: "colour-mode", onchange: (e) => { settings.mode = e.target.value; redraw(); } },
    el("option", { value: "curvature" }, "curvature"), el("option", { value: "contact" }, "contact"),
    components.length > 1 ? el("option", { value: "component" }, "component") : null);
  if (settings.mode === "component" && components.length < 2) settings.mode = "curvature";
  mode.value = settings.mode;
  const thick = el("select", { id: "thickness", onchange: (e) => { settings.thickness = Number(e.target.value); redraw(); } },
    [1, 2, 4, 8].map((f) => el("option", { value: f }, f === 1 ? `r = ${radius} (as stored)` : `${f} × r`)));
  thick.value = String(settings.thickness);
  const order = [...Array(m).keys()].sort((a, b) => value(a, "energy") - value(b, "energy"));
  const compare = el("select", { id: "compare", onchange: (e) => {
    const j = e.target.value;
    location.hash = `#/view/${encodeURIComponent(name)}/${indices[0]}${j === "" ? "" : "/" + j}`;
  } }, el("option", { value: "" }, "none"),
  order.filter((j) => j !== indices[0]).map((j) =>
    el("option", { value: j }, `#${j}: E = ${fmt(value(j, "energy"), 5)}, cluster ${clusters.rank[j]}`)));
  compare.value = indices.length === 2 ? String(indices[1]) : "";
  const legend = el("div", { class: "colorbar", id: "colorbar" });
  const what = fromLedger(site) ? `state${indices.length === 2 ? "s" : ""} (representative${indices.length === 2 ? "s" : ""})`
    : `equilibri${indices.length === 2 ? "a" : "um"}`;
  main.append(el("h2", {}, back, ` · ${what} ${indices.join(" and ")}`),
    el("div", { class: "controls" },
      el("label", {}, "colour ", mode), el("label", {}, "wire ", thick), el("label", {}, "beside it ", compare)),
    legend);
  if (indices.length === 2) {
    const s = k.similarity[indices[0] * m + indices[1]];
    main.append(el("p", { id: "similarity" }, `similarity ${fmt(s, 4)} (distance 1 − similarity = ${fmt(1 - s, 4)}; ` +
      `clusters ${clusters.rank[indices[0]]} and ${clusters.rank[indices[1]]} at the cut ${fmt(cut)})`));
  }
  const row = el("div", { class: "viewers" });
  main.append(row);
  const viewers = indices.map((i) => {
    const box = el("div", { class: "viewer", dataset: { index: i } },
      el("div", { class: "caption" }, `${name} #${i}: E = ${fmt(value(i, "energy"), 5)}, 3D-ness ${fmt(value(i, "threedim"), 3)}`));
    const downloads = el("div", { class: "controls" },
      el("button", { class: "download-curve", onclick: () => download(curveObj(`elastic knot ${name}, equilibrium ${i}`, curve(k, i), components), `${name}_${i}.obj`) }, "curve OBJ"),
      el("button", { class: "download-tube", onclick: () => download(meshObj(`elastic knot ${name}, equilibrium ${i}, tube of radius ${radius * settings.thickness}`, viewer.geometry), `${name}_${i}_tube.obj`) }, "tube OBJ"));
    row.append(el("div", {}, box, downloads));
    const viewer = new TubeViewer(box);
    return { i, box, viewer };
  });
  const attrs = attributeNames(site, k);
  main.append(el("h3", {}, "Attributes"), el("table", { class: "data", id: "attributes" },
    el("thead", {}, el("tr", {}, el("th", {}, "attribute"), indices.map((i) => el("th", {}, `#${i}`)))),
    el("tbody", {}, attrs.map((a) => el("tr", {}, el("td", {}, ATTRIBUTE_LABELS[a] ?? a), indices.map((i) => el("td", {}, fmt(value(i, a), 6))))))));

  function redraw(keepCamera = true) {
    legend.replaceChildren(...(settings.mode === "component"
      ? components.map((size, c) => el("span", {}, el("span", { class: "swatch", style: `background:${clusterColor(c)}` }), `component ${c} (${size} vertices) `))
      : settings.mode === "curvature"
      ? [el("span", {}, "curvature 0"), el("span", { class: "ramp", style: `background:${viridisGradient()}` }),
        el("span", {}, `${fmt(vmax, 3)} / length (99th percentile)`)]
      : [el("span", { class: "swatch", style: `background:rgb(${CONTACT.map((x) => x * 255).join(",")})` }), `closer than d̂ = ${site.dataset.dhat} to another strand`,
        el("span", { class: "swatch", style: `background:rgb(${FREE.map((x) => x * 255).join(",")})` }), "free"]));
    for (const v of viewers) {
      v.viewer.show(curve(k, v.i), colors(k, v.i, settings.mode, vmax), radius * settings.thickness, { keepCamera, components });
      v.box.dataset.drawn = "1";
    }
  }
  redraw(false);
  ready("view");
  return () => viewers.forEach((v) => v.viewer.dispose());
}
