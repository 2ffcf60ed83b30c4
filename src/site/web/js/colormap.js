// Colours of the 3D view: viridis (matplotlib's, 33 samples, linear in
// between) for curvature, red and grey for contact (as in the figures).

const VIRIDIS = [[0.267,0.005,0.329],[0.277,0.050,0.376],[0.282,0.095,0.417],[0.283,0.136,0.453],[0.279,0.175,0.483],[0.271,0.214,0.507],[0.259,0.252,0.525],[0.245,0.288,0.537],[0.230,0.322,0.546],[0.214,0.356,0.551],[0.199,0.388,0.555],[0.186,0.419,0.557],[0.173,0.449,0.558],[0.161,0.479,0.558],[0.149,0.508,0.557],[0.138,0.537,0.555],[0.128,0.567,0.551],[0.121,0.596,0.544],[0.121,0.626,0.533],[0.132,0.655,0.520],[0.158,0.684,0.502],[0.197,0.712,0.479],[0.246,0.739,0.452],[0.304,0.765,0.420],[0.369,0.789,0.383],[0.440,0.811,0.341],[0.516,0.831,0.294],[0.596,0.849,0.243],[0.678,0.864,0.190],[0.762,0.876,0.137],[0.846,0.887,0.100],[0.926,0.897,0.104],[0.993,0.906,0.144]];

export const CONTACT = [0.85, 0.12, 0.10];
export const FREE = [0.72, 0.72, 0.74];

/** sRGB triple in [0, 1] of viridis at t in [0, 1] (clamped). */
export function viridis(t) {
  const x = Math.min(1, Math.max(0, Number.isFinite(t) ? t : 0)) * (VIRIDIS.length - 1);
  const i = Math.min(VIRIDIS.length - 2, Math.floor(x));
  const f = x - i;
  return VIRIDIS[i].map((c, k) => c + f * (VIRIDIS[i + 1][k] - c));
}

/** A CSS linear-gradient of viridis, for colour bars. */
export function viridisGradient() {
  const stops = VIRIDIS.filter((_, i) => i % 4 === 0).map((c, i, a) =>
    `rgb(${c.map((x) => Math.round(x * 255)).join(",")}) ${(100 * i / (a.length - 1)).toFixed(1)}%`);
  return `linear-gradient(to right, ${stops.join(", ")})`;
}

/** The p-th percentile (0..100) of values. */
export function percentile(values, p) {
  const s = Float64Array.from(values).sort();
  if (!s.length) return 0;
  const x = (p / 100) * (s.length - 1);
  const i = Math.floor(x);
  return i + 1 < s.length ? s[i] + (x - i) * (s[i + 1] - s[i]) : s[i];
}
