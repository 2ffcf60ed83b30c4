"""Transitions between stable states (paper Section 8.5, an open direction):
(a) the transition graph of 4_1's states over energy: each state at its
energy (E - E_lowest in units of EI/L), each verified saddle as a marker at
its energy joined to the states its descents reach (a marker above one state:
a saddle between two minima of that state), the double-ended searches as
dashed lines labelled by their status, with the highest image of the
steered chain (hollow square: an upper bound on the barrier) when it
reached B; (b) the energy along each edge's
path, from the state it was searched from over the saddle, E - E_from in
units of EI/L; (c) the puzzle barriers (puzzle_barriers.csv, paper Fig. 14):
per puzzle pair, the barrier of the chain of verified saddles from state_a
when connect_states() joined them (filled), else the steered chain's upper
bound (hollow), labelled by the outcome and the searches run."""
import os

import numpy as np

from common import parse_args, plt, read_csv, read_summary, save, save_empty

a = parse_args(__doc__)
d = f"{a.results}/transitions"
s = read_summary(a.results, "transitions")
states = read_csv(f"{d}/states.csv")
edges = read_csv(f"{d}/edges.csv")
pairs = read_csv(f"{d}/pairs.csv")
profile = read_csv(f"{d}/profile.csv")
if not states:
    save_empty(a.out, "fig_transitions", "no state at this scale")
    raise SystemExit
scale = float(s["energy_scale"])
e = np.array([float(r["energy"]) for r in states])
y = (e - e.min()) / scale

puzzle_file = f"{d}/puzzle_barriers.csv"
puzzles = read_csv(puzzle_file) if os.path.exists(puzzle_file) else []

fig, (ax, bx, cx) = plt.subplots(1, 3, figsize=(15, 4.2))
ax.scatter(np.arange(len(y)), y, s=30, color="tab:blue", zorder=3, label="state")
for k, r in enumerate(states):
    ax.annotate(str(k), (k, y[k]), textcoords="offset points", xytext=(4, -9), fontsize=6)
for r in edges:
    i, j = int(r["from"]), int(r["to"])
    ys = (float(r["saddle_energy"]) - e.min()) / scale
    xs = (i + j) / 2 if i != j else i + 0.15
    color = "tab:red" if r["inter_state"] == "true" else "tab:orange"
    ax.plot([i, xs, j], [y[i], ys, y[j]], "-", color=color, lw=0.8)
    ax.plot([xs], [ys], "v", color=color, ms=5)
for r in pairs:
    i, j = int(r["a"]), int(r["b"])
    ax.plot([i, j], [y[i], y[j]], "--", color="0.6", lw=0.7)
    ax.annotate(r["status"], ((i + j) / 2, (y[i] + y[j]) / 2), fontsize=5, color="0.3", ha="center")
    if r["reached"] == "true":  # the steered chain's highest image: an upper bound on the barrier
        ax.plot([(i + j) / 2], [y[i] + float(r["path_barrier_scaled"])], "s", mfc="none", color="0.4", ms=5)
ax.set_xlabel("state (clusters by energy, then minima matching no cluster)")
ax.set_ylabel("(E - E_lowest) / (EI/L)")
ax.set_title(f"4_1: {s['edges']} edges ({s['inter_state_edges']} between states), "
             f"double-ended {s['pairs_verified']}/{s['pairs_reached']}/{s['pairs']} verified/reached/run",
             fontsize=8)

for k, r in enumerate(edges):
    rows = [p for p in profile if int(p["edge"]) == k]
    pe = np.array([float(p["energy"]) for p in rows])
    at = next(m for m, p in enumerate(rows) if p["saddle"] == "true")
    x = np.arange(len(pe)) - at
    style = "-" if r["inter_state"] == "true" else ":"
    bx.plot(x, (pe - pe[0]) / scale, style, lw=1, label=f"edge {k}: {r['from']}-{r['to']}")
bx.axvline(0, color="0.8", lw=0.8)
bx.set_xlabel("image (0: the saddle)")
bx.set_ylabel("(E - E_from) / (EI/L)")
if edges:
    bx.legend(fontsize=5, ncol=2)
bx.set_title("energy along each edge's path (solid: between states)", fontsize=8)
for k, r in enumerate(puzzles):
    if r["connected"] == "true":
        cx.bar([k], [float(r["barrier_forward_scaled"])], color="tab:red", width=0.6)
        text, top = f"{r['saddles_on_chain']} saddles", float(r["barrier_forward_scaled"])
    elif r["upper_bound_scaled"]:
        top = float(r["upper_bound_scaled"])
        cx.plot([k], [top], "s", mfc="none", color="0.4", ms=6)
        text = r["status"]
    else:
        top, text = 0.0, r["status"][:20]
    cx.annotate(f"{text}, {r['attempts']} searches", (k, top), textcoords="offset points", xytext=(0, 4),
                fontsize=5, ha="center")
cx.set_xticks(range(len(puzzles)))
cx.set_xticklabels([f"{r['knot']} {r['state_a']}-{r['state_b']}" for r in puzzles], fontsize=6, rotation=30)
cx.set_ylabel("barrier from state_a / (EI/L)")
cx.set_title("puzzle barriers (filled: chain of verified saddles; hollow: upper bound)" if puzzles
             else "no puzzle pairs at this scale", fontsize=8)
save(fig, a.out, "fig_transitions")
