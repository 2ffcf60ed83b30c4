// Flat clusters of a stored dendrogram at a cut, computed as `knots cluster`
// does (ek::cut_dendrogram and ek::clusters_at_cut): each merge of height
// <= cut joins the clusters of a representative leaf of each side; clusters
// are ranked by their lowest energy (rank 0: the lowest).

/**
 * linkage: [[a, b, height, size], ...] (SciPy layout, m - 1 rows); energy(i)
 * the energy of equilibrium i. Returns {rank: Int32Array m, count, clusters:
 * [{members, representative, energyMin}] by rank}.
 */
export function clustersAtCut(linkage, m, cut, energy) {
  const rep = new Int32Array(m + Math.max(m - 1, 0));
  const parent = new Int32Array(m);
  for (let i = 0; i < m; i++) { rep[i] = i; parent[i] = i; }
  const find = (x) => { while (parent[x] !== x) x = parent[x] = parent[parent[x]]; return x; };
  linkage.forEach(([a, b, h], k) => {
    const ra = rep[a], rb = rep[b];
    rep[m + k] = ra;
    if (h <= cut) parent[find(rb)] = find(ra);
  });
  const byRoot = new Map();
  for (let i = 0; i < m; i++) {
    const r = find(i);
    if (!byRoot.has(r)) byRoot.set(r, { members: [], representative: i, energyMin: Infinity });
    const c = byRoot.get(r);
    c.members.push(i);
    const e = energy(i);
    if (c.members.length === 1 || e < c.energyMin) { c.energyMin = e; c.representative = i; }
  }
  const clusters = [...byRoot.values()].sort((x, y) => x.energyMin - y.energyMin);
  const rank = new Int32Array(m);
  clusters.forEach((c, r) => c.members.forEach((i) => { rank[i] = r; }));
  return { rank, count: clusters.length, clusters };
}
