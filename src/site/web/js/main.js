// The explorer's entry point: loads data/site.json and shows the view named
// by the URL's hash:
//   #/knots                 the knot types (table.js)
//   #/knot/NAME             one knot: MDS map, dendrogram and cut, equilibria (knot.js)
//   #/view/NAME/I[/J]       equilibrium I (and J beside it) in 3D (view3d.js)
//   #/query?where=...       equilibria of every knot filtered and sorted (query.js)
//   #/milnor                Fig. 9's histogram of the Milnor ratio (milnor.js)
import { loadSite } from "./data.js";
import { showKnotTable } from "./table.js";
import { showKnot } from "./knot.js";
import { showEquilibria } from "./view3d.js";
import { showQuery } from "./query.js";
import { showMilnor } from "./milnor.js";
import { el } from "./util.js";

window.ekStarted = true;
const main = document.getElementById("main");
const errorBox = document.getElementById("error");
let cleanup = null;

function showError(message) {
  errorBox.hidden = false;
  errorBox.textContent = message;
}

function parseHash() {
  const hash = decodeURIComponent(location.hash.replace(/^#\/?/, ""));
  const [path, query = ""] = hash.split("?");
  return { parts: path.split("/").filter(Boolean), params: new URLSearchParams(query) };
}

async function route(site) {
  const { parts, params } = parseHash();
  const view = parts[0] || "knots";
  if (cleanup) { cleanup(); cleanup = null; }
  delete document.body.dataset.ready;
  errorBox.hidden = true;
  for (const a of document.querySelectorAll("nav a")) a.classList.toggle("active", a.dataset.nav === view);
  main.replaceChildren();
  try {
    if (view === "knots") cleanup = showKnotTable(main, site);
    else if (view === "knot") cleanup = await showKnot(main, site, parts[1]);
    else if (view === "view") cleanup = await showEquilibria(main, site, parts[1], parts.slice(2).map(Number));
    else if (view === "query") cleanup = await showQuery(main, site, params);
    else if (view === "milnor") cleanup = showMilnor(main, site);
    else main.append(el("p", {}, `Unknown page #/${view}. `, el("a", { href: "#/knots" }, "Knot types")));
  } catch (e) {
    showError(e.message);
  }
}

try {
  const site = await loadSite();
  const d = site.dataset;
  document.getElementById("title").textContent = `Elastic knots: ${d.title}`;
  document.getElementById("dataset-info").textContent =
    `${site.knots.length} knot types, ${site.attributes.rows} equilibria` +
    `${d.source === "ledger" ? " (from ledgers: a knot shows its states with a kept curve)" : ""}; n = ${d.vertices}, r = ${d.radius}, ` +
    `E = ${d.young}, sampling ${d.sampling}, seed ${d.seed}`;
  window.addEventListener("hashchange", () => route(site));
  await route(site);
} catch (e) {
  main.replaceChildren();
  showError(`The data set could not be loaded: ${e.message}`);
}
