// View: the knot types of the data set, sortable, with filters; a row opens the knot.
import { el, fmt, sortableTable, ready } from "./util.js";

// Filter values survive navigation (module state).
const filters = { name: "", crossingsMin: "", crossingsMax: "", bb: "any", alternating: "any", threedimMin: "" };

const COLUMNS = [
  { key: "name", label: "knot", value: (k) => k.name },
  { key: "crossing_number", label: "crossings", value: (k) => k.crossing_number },
  { key: "bridge_index", label: "bridge", value: (k) => k.bridge_index },
  { key: "braid_index", label: "braid", value: (k) => k.braid_index },
  { key: "bb", label: "BB", value: (k) => k.bb },
  { key: "alternating", label: "alternating", value: (k) => k.alternating },
  { key: "samples", label: "samples", value: (k) => k.samples },
  { key: "equilibria", label: "equilibria", value: (k) => k.equilibria },
  { key: "distinct", label: "distinct", value: (k) => k.distinct },
  { key: "lowest_energy", label: "lowest energy", value: (k) => k.lowest_energy },
  { key: "largest_threedim", label: "largest 3D-ness", value: (k) => k.largest_threedim },
  { key: "milnor_ratio", label: "Milnor ratio", value: (k) => k.milnor_ratio },
];

function keep(k) {
  const num = (s) => (s === "" ? null : Number(s));
  const cmin = num(filters.crossingsMin), cmax = num(filters.crossingsMax), tmin = num(filters.threedimMin);
  if (filters.name && !k.name.toLowerCase().includes(filters.name.toLowerCase())) return false;
  if (cmin !== null && !(k.crossing_number >= cmin)) return false;
  if (cmax !== null && !(k.crossing_number <= cmax)) return false;
  if (filters.bb !== "any" && k.bb !== (filters.bb === "yes")) return false;
  if (filters.alternating !== "any" && k.alternating !== (filters.alternating === "yes")) return false;
  if (tmin !== null && !(k.largest_threedim >= tmin)) return false;
  return true;
}

export function showKnotTable(main, site) {
  const count = el("span", { id: "knot-count", class: "muted" });
  const table = sortableTable(COLUMNS, {
    onRow: (k) => { location.hash = `#/knot/${encodeURIComponent(k.name)}`; },
    rowAttrs: (k) => ({ dataset: { knot: k.name } }),
    sort: { key: "crossing_number" },
  });
  function update() {
    const rows = site.knots.filter(keep);
    table.render(rows);
    count.textContent = `${rows.length} of ${site.knots.length} knot types`;
  }
  const input = (key, attrs) => el("input", { ...attrs, id: `filter-${key}`, value: filters[key],
    oninput: (e) => { filters[key] = e.target.value; update(); } });
  const choice = (key) => {
    const s = el("select", { id: `filter-${key}`, onchange: (e) => { filters[key] = e.target.value; update(); } },
      ["any", "yes", "no"].map((v) => el("option", { value: v }, v)));
    s.value = filters[key];
    return s;
  };
  main.append(
    el("h2", {}, "Knot types"),
    el("p", { class: "muted" }, `Distinct states at the cut ${fmt(site.cut)} (1 − similarity, complete linkage); ` +
      "Milnor ratio: the smallest total curvature over 2π·bridge index. Click a knot to explore its equilibria."),
    el("div", { class: "filters" },
      el("label", {}, "name contains", input("name", { type: "text", size: 8 })),
      el("label", {}, "crossings ≥", input("crossingsMin", { type: "number", min: 0 })),
      el("label", {}, "crossings ≤", input("crossingsMax", { type: "number", min: 0 })),
      el("label", {}, "BB", choice("bb")),
      el("label", {}, "alternating", choice("alternating")),
      el("label", {}, "largest 3D-ness ≥", input("threedimMin", { type: "number", step: 0.05, min: 0, max: 1 })),
      count),
    el("div", { class: "scroll" }, table.node));
  update();
  ready("knots");
  return null;
}
