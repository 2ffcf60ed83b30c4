// Loading the site's data files (written by `knots site`; docs/explorer.md):
// data/site.json, data/attributes.bin and data/knots/<file>.json|.bin.

export const FORMAT = "elastic-knots-site";
export const FORMAT_VERSION = 2;

async function fetchOk(url, kind) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${url}: HTTP ${r.status}`);
  return kind === "json" ? r.json() : r.arrayBuffer();
}

function checkFormat(json, format, url) {
  if (json.format !== format) throw new Error(`${url} is not a ${format} file`);
  if (json.format_version !== FORMAT_VERSION)
    throw new Error(`${url} has format version ${json.format_version}; this page reads version ${FORMAT_VERSION}: rewrite the site with this program's knots site`);
}

/** data/site.json, with `byName` (name -> knot record, which has `index`). */
export async function loadSite() {
  const url = "data/site.json";
  const site = await fetchOk(url, "json");
  checkFormat(site, FORMAT, url);
  site.byName = new Map(site.knots.map((k, i) => [k.name, Object.assign(k, { index: i })]));
  site.column = new Map(site.attribute_names.map((n, i) => [n, i]));
  return site;
}

let attributes = null;
/** Every equilibrium's attributes: Float64Array [rows * columns] (knots in file
 *  order); loaded only by the views across knots (the query view). */
export async function loadAttributes(site) {
  if (!attributes) {
    const buf = await fetchOk("data/" + site.attributes.file, "bin");
    const { rows, columns } = site.attributes;
    if (buf.byteLength !== rows * columns * 8) throw new Error("data/attributes.bin: unexpected size");
    attributes = new Float64Array(buf);
  }
  return attributes;
}

/** Whether the site was written from ledgers: a knot's files then hold its
 *  shown states (those with a kept curve, each as its representative), not
 *  every equilibrium; site.json still has every equilibrium's attributes. */
export function fromLedger(site) {
  return site.dataset.source === "ledger";
}

/** The index in the knot's files (3D view) of its equilibrium i (row i from
 *  the knot's offset in attributes.bin); -1 when a ledger keeps no curve of it. */
export function shownIndex(rec, i) {
  return rec.shown_rows ? rec.shown_rows.indexOf(i) : i;
}

/** Attribute `name` of equilibrium i of a knot, from the table of every
 *  equilibrium (loadAttributes()). */
export function attribute(site, table, knot, i, name) {
  const c = site.column.get(name);
  return c === undefined ? null : table[(knot.offset + i) * site.attribute_names.length + c];
}

/** Attribute `name` of equilibrium i of a loaded knot (loadKnot()). */
export function knotAttribute(site, k, i, name) {
  const names = attributeNames(site, k), c = names.indexOf(name);
  return c < 0 ? null : k.attributes[i * names.length + c];
}

/** The attribute columns of a knot's equilibria: a link has its own (k.attribute_names). */
export function attributeNames(site, k) {
  return k.attribute_names ?? site.attribute_names;
}

/** Vertices per component, back to back: [n] for a knot. */
export function componentSizes(k) {
  return k.components ?? [k.vertices];
}

const knots = new Map();
/** A knot's data, loaded when the knot is opened: its JSON fields and typed
 *  arrays attributes [m*columns], positions [m*n*3], curvature [m*n],
 *  similarity [m*m], contact [m*n]. */
export function loadKnot(site, name) {
  if (!knots.has(name)) knots.set(name, (async () => {
    const rec = site.byName.get(name);
    if (!rec) throw new Error(`no knot ${name} in this data set`);
    const url = `data/knots/${rec.file}.json`;
    const k = await fetchOk(url, "json");
    checkFormat(k, FORMAT + "-knot", url);
    const buf = await fetchOk(`data/knots/${k.binary}`, "bin");
    if (buf.byteLength !== k.binary_bytes) throw new Error(`data/knots/${k.binary}: unexpected size`);
    const view = (b, T) => new T(buf, b.offset, b.shape.reduce((x, y) => x * y, 1));
    k.attributes = view(k.buffers.attributes, Float64Array);
    k.positions = view(k.buffers.positions, Float32Array);
    k.curvature = view(k.buffers.curvature, Float32Array);
    k.similarity = view(k.buffers.similarity, Float32Array);
    k.contact = view(k.buffers.contact, Uint8Array);
    k.record = rec;
    return k;
  })());
  return knots.get(name);
}

/** Positions of equilibrium i (Float32Array n*3, a view). */
export function curve(k, i) {
  const n = k.vertices;
  return k.positions.subarray(i * n * 3, (i + 1) * n * 3);
}
