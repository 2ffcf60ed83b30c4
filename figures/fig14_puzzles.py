"""Fig. 14: knot puzzles. Pairs of distinct stable states of one knot with the
same writhe (hence the same link for the joined wire): the two states'
shadows and the link of the puzzle."""
from common import draw_three_shadows, parse_args, plt, read_csv, read_obj, read_summary, save

a = parse_args(__doc__)
rows = read_csv(f"{a.results}/puzzles/puzzles.csv")
s = read_summary(a.results, "puzzles")


# one puzzle per knot, the pair with the most different shapes (lowest similarity)
best = {}
for r in rows:
    if r["knot"] not in best or float(r["similarity"]) < float(best[r["knot"]]["similarity"]):
        best[r["knot"]] = r
shown = sorted(best.values(), key=lambda r: float(r["similarity"]))[:4]
if not shown:
    fig, ax = plt.subplots(figsize=(4, 1))
    ax.text(0.5, 0.5, "no puzzle found at this scale", ha="center")
    ax.axis("off")
    save(fig, a.out, "fig14_puzzles")
    raise SystemExit
fig, axs = plt.subplots(3, 2 * len(shown), figsize=(3.2 * len(shown), 4.6), squeeze=False)
for p, r in enumerate(shown):
    for side, (curve, energy) in enumerate(((r["curve_a"], r["energy_a"]), (r["curve_b"], r["energy_b"]))):
        col = 2 * p + side
        draw_three_shadows([axs[0][col], axs[1][col], axs[2][col]], read_obj(f"{a.results}/puzzles/{curve}"))
        axs[0][col].set_title(f"{r['knot']} state {'AB'[side]}\nE = {float(energy):.3f}", fontsize=7)
    axs[2][2 * p].set_xlabel(f"link {float(r['link']):.2f} (≈ {r['link_rounded']})", fontsize=8)
fig.suptitle(f"puzzles: {s['puzzles']} pairs of states with equal writhe (±{s['writhe_tolerance']}) "
             f"in {s['knots_with_puzzles']} knots", fontsize=10)
save(fig, a.out, "fig14_puzzles")
