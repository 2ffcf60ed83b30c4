// View: cross-knot queries, as `knots query`: keep the equilibria for which
// every condition ATTR OP VALUE holds (OP: < <= > >= = == !=), in file order
// (knots as in the data set, equilibria by index), then sort stably by one
// attribute (ascending, or descending with :desc) and keep the first K. The
// query lives in the address (#/query?knot=&where=energy<2&sort=energy:desc&limit=10),
// so it can be bookmarked; a row opens the equilibrium in 3D (in a site of
// ledgers, only a shown state's representative has a curve to open).
import { loadAttributes, shownIndex } from "./data.js";
import { el, fmt, ATTRIBUTE_LABELS, ready } from "./util.js";

const OPS = ["<", "<=", ">", ">=", "=", "!="];
const SHOWN = 1000;  // rows drawn at most (the count is always exact)

/** {attribute, op, value} of "ATTR<VALUE", as knots query parses --where. */
export function parseCondition(text) {
  for (const op of ["<=", ">=", "!=", "==", "<", ">", "="]) {
    const p = text.indexOf(op);
    if (p <= 0) continue;
    const valueText = text.slice(p + op.length).trim();
    const value = Number(valueText);
    if (valueText === "" || !Number.isFinite(value)) throw new Error(`--where '${text}': '${valueText}' is not a number`);
    return { attribute: text.slice(0, p), op, value };
  }
  throw new Error(`--where '${text}': expected ATTR<VALUE (operators < <= > >= = !=)`);
}

function holds(op, x, v) {
  switch (op) {
    case "<": return x < v;
    case "<=": return x <= v;
    case ">": return x > v;
    case ">=": return x >= v;
    case "=": case "==": return x === v;
    default: return x !== v;
  }
}

/** The rows of a query: [{knot, index, row}] (row: index into the attribute table). */
export function runQuery(site, table, { knot, where, sort, limit }) {
  const names = site.attribute_names, k = names.length;
  const column = (a) => {
    if (!site.column.has(a)) throw new Error(`unknown attribute '${a}'; known: ${names.join(", ")}`);
    return site.column.get(a);
  };
  const conditions = where.map(parseCondition).map((c) => ({ ...c, col: column(c.attribute) }));
  let sortCol = null, desc = false;
  if (sort) {
    const [attr, dir = "asc"] = sort.split(":");
    if (dir !== "asc" && dir !== "desc") throw new Error(`--sort '${sort}': direction must be asc or desc`);
    sortCol = column(attr);
    desc = dir === "desc";
  }
  const knots = knot ? [site.byName.get(knot)] : site.knots;
  if (knot && !knots[0]) throw new Error(`no knot ${knot} in this data set`);
  const rows = [];
  for (const rec of knots) {
    for (let i = 0; i < rec.equilibria; i++) {
      const r = rec.offset + i;
      if (conditions.every((c) => holds(c.op, table[r * k + c.col], c.value))) rows.push({ knot: rec.name, index: i, row: r });
    }
  }
  if (sortCol !== null) {
    const v = (x) => table[x.row * k + sortCol];
    rows.sort((a, b) => (desc ? (v(a) > v(b) ? -1 : v(b) > v(a) ? 1 : 0) : (v(a) < v(b) ? -1 : v(b) < v(a) ? 1 : 0)));
  }
  return limit !== null && limit !== undefined && rows.length > limit ? rows.slice(0, limit) : rows;
}

/** A result row: opens the 3D view of its curve; muted without one (a ledger keeps few curves). */
function viewRow(site, r, ...cells) {
  const view = shownIndex(site.byName.get(r.knot), r.index);
  const open = () => { location.hash = `#/view/${encodeURIComponent(r.knot)}/${view}`; };
  return el("tr", { dataset: { knot: r.knot, index: r.index, view }, class: view < 0 ? "no-curve" : null,
    title: view < 0 ? "the ledger keeps no curve of this equilibrium" : null, onclick: view < 0 ? null : open }, ...cells);
}

function conditionRow(site, text = "") {
  let c = { attribute: site.attribute_names[0], op: "<", value: "" };
  if (text) { try { c = parseCondition(text); } catch { /* shown empty */ } }
  const attr = el("select", { class: "cond-attr" }, site.attribute_names.map((a) => el("option", { value: a }, ATTRIBUTE_LABELS[a] && ATTRIBUTE_LABELS[a] !== a ? `${a} (${ATTRIBUTE_LABELS[a]})` : a)));
  attr.value = c.attribute;
  const op = el("select", { class: "cond-op" }, OPS.map((o) => el("option", { value: o }, o)));
  op.value = c.op === "==" ? "=" : c.op;
  const value = el("input", { class: "cond-value", type: "text", size: 10, value: c.value });
  const row = el("div", { class: "condition" }, attr, op, value,
    el("button", { type: "button", onclick: () => row.remove() }, "remove"));
  row.text = () => (value.value.trim() === "" ? null : `${attr.value}${op.value}${value.value.trim()}`);
  return row;
}

export async function showQuery(main, site, params) {
  const table = await loadAttributes(site);
  const q = { knot: params.get("knot") || "", where: params.getAll("where"), sort: params.get("sort") || "",
    limit: params.get("limit") };
  const knotSel = el("select", { id: "query-knot" }, el("option", { value: "" }, "every knot"),
    site.knots.map((k) => el("option", { value: k.name }, k.name)));
  knotSel.value = q.knot;
  const conditions = el("div", { id: "conditions" }, q.where.map((w) => conditionRow(site, w)));
  const [sortAttr, sortDir = "asc"] = q.sort ? q.sort.split(":") : ["", "asc"];
  const sortSel = el("select", { id: "query-sort" }, el("option", { value: "" }, "file order"),
    site.attribute_names.map((a) => el("option", { value: a }, a)));
  sortSel.value = sortAttr;
  const dirSel = el("select", { id: "query-dir" }, el("option", { value: "asc" }, "ascending"), el("option", { value: "desc" }, "descending"));
  dirSel.value = sortDir;
  const limit = el("input", { id: "query-limit", type: "number", min: 0, value: q.limit ?? "", placeholder: "all" });
  const run = el("button", { id: "query-run", type: "button", onclick: () => {
    const p = new URLSearchParams();
    if (knotSel.value) p.set("knot", knotSel.value);
    for (const row of conditions.children) { const t = row.text(); if (t) p.append("where", t); }
    if (sortSel.value) p.set("sort", `${sortSel.value}:${dirSel.value}`);
    if (limit.value !== "") p.set("limit", limit.value);
    const hash = `#/query?${p.toString()}`;
    if (location.hash === hash) window.dispatchEvent(new HashChangeEvent("hashchange"));
    else location.hash = hash;
  } }, "Run");
  main.append(el("h2", {}, "Query the equilibria of every knot"),
    el("p", { class: "muted" }, "Combined filters (all must hold) and a sort, as ", el("code", {}, "knots query"),
      " takes them; for example sphericity < 0.05 and 3D-ness < 0.1 finds multi-covered circles (paper Section 7.3)."),
    el("div", { class: "filters" }, el("label", {}, "knot", knotSel),
      el("label", {}, "sort by", sortSel), el("label", {}, "order", dirSel), el("label", {}, "at most", limit)),
    el("h3", {}, "conditions"), conditions,
    el("div", { class: "controls" }, el("button", { type: "button", id: "query-add", onclick: () => conditions.append(conditionRow(site)) }, "add condition"), run));

  const result = el("div", { id: "query-result" });
  main.append(result);
  const hasQuery = [...params.keys()].length > 0;
  if (hasQuery) {
    const rows = runQuery(site, table, { knot: q.knot || null, where: q.where, sort: q.sort || null,
      limit: q.limit === null || q.limit === "" ? null : Number(q.limit) });
    const names = site.attribute_names;
    result.append(el("p", {}, el("strong", { id: "query-count" }, String(rows.length)), " equilibria",
      rows.length > SHOWN ? ` (the first ${SHOWN} shown)` : ""),
    el("div", { class: "scroll" }, el("table", { class: "data", id: "query-table" },
      el("thead", {}, el("tr", {}, el("th", {}, "knot"), el("th", {}, "index"), names.map((a) => el("th", {}, ATTRIBUTE_LABELS[a] ?? a)))),
      el("tbody", {}, rows.slice(0, SHOWN).map((r) => viewRow(site, r,
      el("td", {}, r.knot), el("td", {}, r.index), names.map((a, c) => el("td", {}, fmt(table[r.row * names.length + c], 6)))))))));
  } else if (!conditions.children.length) {
    conditions.append(conditionRow(site));
  }
  ready("query");
  return null;
}
