// Small helpers shared by the views: elements, number formatting, sortable tables, colours.

/** An element with attributes (on* are listeners) and children (strings or nodes). */
export function el(tag, attrs = {}, ...children) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k.startsWith("on")) node.addEventListener(k.slice(2), v);
    else if (k === "dataset") Object.assign(node.dataset, v);
    else node.setAttribute(k, v === true ? "" : v);
  }
  for (const c of children.flat()) if (c !== null && c !== undefined) node.append(c instanceof Node ? c : String(c));
  return node;
}

/** An SVG element with attributes. */
export function svg(tag, attrs = {}, ...children) {
  const node = document.createElementNS("http://www.w3.org/2000/svg", tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k.startsWith("on")) node.addEventListener(k.slice(2), v);
    else if (k === "dataset") Object.assign(node.dataset, v);
    else node.setAttribute(k, v);
  }
  for (const c of children.flat()) if (c !== null && c !== undefined) node.append(c instanceof Node ? c : String(c));
  return node;
}

/** A number for tables: 4 significant digits, "–" for null or NaN. */
export function fmt(x, digits = 4) {
  if (x === null || x === undefined || Number.isNaN(x)) return "–";
  if (typeof x === "boolean") return x ? "yes" : "no";
  if (typeof x !== "number") return String(x);
  if (Number.isInteger(x) && Math.abs(x) < 1e6) return String(x);
  const s = x !== 0 && (Math.abs(x) >= 1e5 || Math.abs(x) < 1e-3) ? x.toExponential(digits - 1) : x.toPrecision(digits);
  const [mantissa, exponent] = s.split("e");
  const trimmed = mantissa.includes(".") ? mantissa.replace(/0+$/, "").replace(/\.$/, "") : mantissa;
  return exponent === undefined ? trimmed : `${trimmed}e${exponent}`;
}

/** Labels of the attribute columns (names as in the data set). */
export const ATTRIBUTE_LABELS = {
  energy: "energy", energy_stretch: "stretch", energy_bend: "bend", energy_twist: "twist",
  energy_contact: "contact energy", stiffness: "stiffness", max_stress: "max stress",
  total_curvature: "total curvature", threedim: "3D-ness", sphericity: "sphericity", diameter: "diameter",
  writhe: "writhe", link: "link", contacts: "contacts", sample: "sample",
};

/** Cluster colours (matplotlib's tab10, then tab10 lighter). */
const TAB10 = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"];
export function clusterColor(k) {
  const base = TAB10[k % 10];
  return k < 10 ? base : base + (k < 20 ? "99" : "55");
}

/**
 * A sortable table. columns: [{key, label, value(row), format?(v)}]; rows: any
 * objects; onRow(row) on click; rowAttrs(row) gives extra attributes of a <tr>.
 * Returns {node, render(rows)}; clicking a header sorts by it (again: reverses).
 */
export function sortableTable(columns, { onRow, rowAttrs, sort } = {}) {
  const state = { key: sort?.key ?? null, desc: sort?.desc ?? false, rows: [] };
  const thead = el("thead");
  const tbody = el("tbody");
  const table = el("table", { class: "data" }, thead, tbody);
  function header() {
    thead.replaceChildren(el("tr", {}, columns.map((c) =>
      el("th", {
        class: state.key === c.key ? (state.desc ? "sorted-desc" : "sorted-asc") : null,
        dataset: { key: c.key },
        onclick: () => { state.desc = state.key === c.key ? !state.desc : false; state.key = c.key; render(state.rows); },
      }, c.label))));
  }
  function render(rows) {
    state.rows = rows;
    let shown = rows;
    if (state.key !== null) {
      const col = columns.find((c) => c.key === state.key);
      const v = (r) => { const x = col.value(r); return x === null || x === undefined || Number.isNaN(x) ? null : x; };
      shown = [...rows].sort((a, b) => {
        const x = v(a), y = v(b);
        if (x === y) return 0;
        if (x === null) return 1;
        if (y === null) return -1;
        return (x < y ? -1 : 1) * (state.desc ? -1 : 1);
      });
    }
    header();
    tbody.replaceChildren(...shown.map((r) => el("tr", { ...(rowAttrs ? rowAttrs(r) : {}), onclick: onRow ? () => onRow(r) : null },
      columns.map((c) => el("td", {}, (c.format ?? fmt)(c.value(r)))))));
  }
  header();
  return { node: table, render };
}

/** Marks the view as drawn (the browser tests wait for it), with the time since the page's navigation started [ms]. */
export function ready(name) {
  document.body.dataset.readyAt = performance.now().toFixed(1);
  document.body.dataset.ready = name;
}
