"""Fig. 14: knot puzzles. Pairs of distinct stable states of one knot with the
same writhe (hence the same link for the joined wire): the two states from
the top and the front, as tubes of the wire's radius coloured by contact
(red: closer than the contact distance d̂ to another strand), since the
states differ in their contact patterns, and the link of the puzzle."""
from common import (contact_legend, draw_views, parse_args, plt, read_csv, read_obj, read_summary, save, save_empty,
                    summary_radius)

SCALE = 2.0  # wire drawn at this multiple of its radius

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
    save_empty(a.out, "fig14_puzzles", "no puzzle found at this scale")
    raise SystemExit
radius = summary_radius(s, "puzzles")
dhat = s["dhat"]
fig, axs = plt.subplots(2, 2 * len(shown), figsize=(3.3 * len(shown), 3.9), squeeze=False,
                        gridspec_kw={"height_ratios": [1.0, 0.6], "hspace": 0.15, "wspace": 0.05})
for p, r in enumerate(shown):
    for side, (curve, energy) in enumerate(((r["curve_a"], r["energy_a"]), (r["curve_b"], r["energy_b"]))):
        col = 2 * p + side
        draw_views([axs[0][col], axs[1][col]], read_obj(f"{a.results}/puzzles/{curve}"), labels=False,
                   radius=radius, radius_scale=SCALE, color="contact", dhat=dhat)
        pair = (f"{r['knot']}, link {float(r['link']):.2f} (≈ {r['link_rounded']})" if side == 0 else
                f"similarity {float(r['similarity']):.2f}")
        axs[0][col].set_title(f"{pair}\nstate {'AB'[side]}: E = {float(energy):.3f}", fontsize=7)
axs[0][0].set_ylabel("top", fontsize=7)
axs[1][0].set_ylabel("front", fontsize=7)
contact_legend(fig, loc="lower center", ncol=2, fontsize=7, frameon=False, bbox_to_anchor=(0.5, -0.04))
fig.suptitle(f"puzzles: {s['puzzles']} pairs of states with equal writhe (±{s['writhe_tolerance']}) "
             f"in {s['knots_with_puzzles']} knots (wire drawn at {SCALE:g}× its radius r = {radius:g}; "
             f"red: contact, closer than d̂ = {dhat:g})", fontsize=8)
save(fig, a.out, "fig14_puzzles")
