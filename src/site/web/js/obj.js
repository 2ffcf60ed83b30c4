// OBJ downloads of an equilibrium: the curve (v and l lines, the format
// `knots` reads) and the tube mesh (v, vn, f) for rendering or printing.

/** The curve as OBJ text, a closed loop of l lines per component (vertex
 *  counts `components`); positions are float32 as stored in the site. */
export function curveObj(title, points, components = [points.length / 3]) {
  const n = points.length / 3;
  const lines = [`# ${title}`,
    "# float32 coordinates from the explorer; `knots export DATASET NAME INDEX -o FILE.obj` writes the stored double-precision curve"];
  for (let i = 0; i < n; i++) lines.push(`v ${points[3 * i]} ${points[3 * i + 1]} ${points[3 * i + 2]}`);
  let start = 0;
  for (const c of components) {
    for (let i = 0; i < c; i++) lines.push(`l ${start + i + 1} ${start + ((i + 1) % c) + 1}`);
    start += c;
  }
  return lines.join("\n") + "\n";
}

/** A three.js indexed BufferGeometry (the tube) as OBJ text. */
export function meshObj(title, geometry) {
  const p = geometry.getAttribute("position").array, nrm = geometry.getAttribute("normal").array;
  const idx = geometry.getIndex().array;
  const out = [`# ${title}`];
  for (let i = 0; i < p.length; i += 3) out.push(`v ${p[i]} ${p[i + 1]} ${p[i + 2]}`);
  for (let i = 0; i < nrm.length; i += 3) out.push(`vn ${nrm[i]} ${nrm[i + 1]} ${nrm[i + 2]}`);
  for (let i = 0; i < idx.length; i += 3) {
    const [a, b, c] = [idx[i] + 1, idx[i + 1] + 1, idx[i + 2] + 1];
    out.push(`f ${a}//${a} ${b}//${b} ${c}//${c}`);
  }
  return out.join("\n") + "\n";
}

/** Offers text as a file download. */
export function download(text, filename) {
  const url = URL.createObjectURL(new Blob([text], { type: "text/plain" }));
  const a = document.createElement("a");
  a.href = url;
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
