// View: one knot type. Its MDS map and dendrogram coloured by the clusters at
// a cut the slider sets (reclustered here exactly as `knots cluster` does),
// the count of distinct states, and its equilibria with their attributes
// (sortable), and a row of pictures of its states at the cut sorted by energy
// (gallery.js); a point, a row or a picture opens the equilibrium in 3D. A site of
// ledgers shows the knot's states with a kept curve (their representatives).
import { loadKnot, knotAttribute, attributeNames, fromLedger } from "./data.js";
import { clustersAtCut } from "./clusters.js";
import { mdsPlot } from "./mds.js";
import { dendrogramPlot } from "./dendrogram.js";
import { stateGallery } from "./gallery.js";
import { el, fmt, sortableTable, clusterColor, ATTRIBUTE_LABELS, ready } from "./util.js";

export async function showKnot(main, site, name) {
  const rec = site.byName.get(name);
  if (!rec) throw new Error(`no knot ${name} in this data set`);
  const k = await loadKnot(site, name);
  const m = k.equilibria;
  const value = (i, a) => knotAttribute(site, k, i, a);
  const ledger = fromLedger(site);
  const counts = ledger
    ? `${rec.samples} samples, ${rec.equilibria} stable equilibria in ${k.states} states at the ledger's cut ` +
      `${fmt(site.dataset.ledger_cut)}; shown: the ${m} lowest-energy states whose curve the ledger keeps, each as its representative.`
    : `${rec.samples} samples, ${m} stable equilibria.`;
  const u = k.unseen;
  const unseen = u && u.samples > 0
    ? el("p", { class: "muted", id: "unseen" },
      `States not yet seen (${ledger ? "the ledger's cut" : `cut ${fmt(site.cut)}`}): ${u.found} found, about ` +
      `${fmt(Math.round(u.estimated))} in all (Chao1; 95% interval ${fmt(Math.round(u.lower))} to ${fmt(Math.round(u.upper))}); ` +
      `the next sample finds a new state with a chance of ${fmt(u.new_state_probability, 2)}, a new one within 1.1 of ` +
      `the lowest energy with ${fmt(k.unseen_low_energy.new_state_probability, 2)}.`)
    : null;
  main.append(el("h2", {}, `${name}`),
    el("p", { class: "muted" },
      `${rec.crossing_number} crossings, bridge index ${fmt(rec.bridge_index)}, braid index ${fmt(rec.braid_index)}` +
      `${rec.bb ? " (BB)" : ""}, ${rec.alternating === null ? "" : rec.alternating ? "alternating, " : "non-alternating, "}` +
      counts), unseen);
  if (m === 0) {
    main.append(el("p", {}, ledger && rec.equilibria > 0
      ? "The ledger keeps no curve of this knot's states (rerunning a state's sample reproduces it)."
      : "No stable equilibrium is stored for this knot."));
    ready("knot");
    return null;
  }
  const open = (i) => { location.hash = `#/view/${encodeURIComponent(name)}/${i}`; };
  const mds = mdsPlot(k, { onClick: open, energy: (i) => value(i, "energy") });
  let cut = k.cut ?? site.cut;  // a link's cut is in its state distance (data/knots/NAME.json)
  const dendro = dendrogramPlot(k, { onPick: (h) => setCut(h) });
  const slider = el("input", { type: "range", id: "cut-slider", min: 0, max: 1, step: 0.0005, value: cut,
    oninput: (e) => setCut(Number(e.target.value)) });
  const number = el("input", { type: "number", id: "cut-value", min: 0, max: 1, step: 0.001, value: cut,
    onchange: (e) => { const c = Number(e.target.value); if (c >= 0 && c <= 1) setCut(c); } });
  const count = el("strong", { id: "cluster-count" });
  const gallery = stateGallery(k, site.dataset.radius, (i) => value(i, "energy"), open);
  const attrs = attributeNames(site, k).filter((a) => a !== "sample");
  let clusters = null;
  const rows = Array.from({ length: m }, (_, i) => ({ i }));
  const columns = [
    { key: "index", label: "#", value: (r) => r.i },
    ...(ledger ? [{ key: "members", label: "members", value: (r) => k.members[r.i] }] : []),
    { key: "cluster", label: "cluster", value: (r) => clusters.rank[r.i],
      format: (c) => el("span", {}, el("span", { class: "swatch", style: `background:${clusterColor(c)}` }), c) },
    ...attrs.map((a) => ({ key: a, label: ATTRIBUTE_LABELS[a] ?? a, value: (r) => value(r.i, a) })),
  ];
  const eqTable = sortableTable(columns, {
    onRow: (r) => open(r.i),
    rowAttrs: (r) => ({ dataset: { index: r.i }, class: clusters.clusters[clusters.rank[r.i]].representative === r.i ? "representative" : null }),
    sort: { key: "energy" },
  });
  function setCut(c) {
    cut = c;
    slider.value = c;
    number.value = c;
    clusters = clustersAtCut(k.linkage, m, cut, (i) => value(i, "energy"));
    const reps = new Set(clusters.clusters.map((x) => x.representative));
    mds.color(clusters.rank, reps);
    dendro.setCut(cut, clusters.rank);
    gallery.render(clusters);
    count.textContent = `${clusters.count}`;
    count.dataset.cut = String(cut);
    eqTable.render(rows);
  }
  main.append(
    el("div", { class: "cut" }, el("label", { for: "cut-slider" }, "cut (1 − similarity)"), slider, number,
      el("span", {}, count, " distinct states (clusters) at this cut; the largest point of a colour is its lowest-energy member")),
    el("h3", {}, "States at this cut, lowest energy first (each its lowest-energy member; click one for 3D)"),
    gallery.node,
    el("div", { class: "row" }, el("div", { class: "panel" }, mds.node), el("div", { class: "panel" }, dendro.node)),
    el("h3", {}, `${ledger ? "States (representatives; " : "Equilibria ("}click one for 3D; bold: the lowest energy of its cluster)`),
    el("div", { class: "scroll" }, eqTable.node));
  setCut(cut);
  ready("knot");
  return null;
}
