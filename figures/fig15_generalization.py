"""Fig. 15: constructive generalization. Top left: 9_35's state of three
intertwined circles (the table's PD drawing relaxed). Top right: the data
set's equilibria closest to it (ICP alignment), aligned onto it, with their
knot types and distances. Bottom: the pretzel knots P(p,q,r) built with p, q
and r crossings in the three touching regions, relaxed: crossings, whether a
table knot shares the Alexander polynomial, energy, 3D-ness, similarity to
9_35's state and the three-circle fit. Two views each (top, front)."""
from common import dataset_material, draw_framed, frame_of, parse_args, plt, read_obj, read_summary, save

a = parse_args(__doc__)
s = read_summary(a.results, "generalization")
radius, _ = dataset_material(f"{a.results}/{s['dataset']}")  # the members are relaxed with its model
folder = f"{a.results}/generalization"
hits = s["search"][:5]
members = s["members"]
cols = max(1 + len(hits), len(members))
fig, axs = plt.subplots(4, cols, figsize=(1.7 * cols, 7.4), squeeze=False)
pattern = read_obj(f"{folder}/{s['pattern']['curve']}")
frame = frame_of(pattern)


def circles(m):
    c = m["circles"]
    return f"circles {c['relative_rms']:.3f}{' ✓' if c['three_circles'] else ''}"


p = s["pattern"]
top = [(pattern, f"9_35 ({p['route']})\nE {p['energy']:.3f}, 3D {p['threedim']:.2f}\n{circles(p)}", frame)]
top += [(read_obj(f"{folder}/{h['curve']}"), f"{h['rank']}. {h['knot']} #{h['index']}\nd = {h['distance']:.2f}, "
         f"3D {h['threedim']:.2f}\n{circles(h)}", frame) for h in hits]
bottom = []
for m in members:
    P = read_obj(f"{folder}/{m['curve']}")
    table = ", ".join(m["table_knots"]) if m["table_knots"] else "no table knot"
    bottom.append((P, f"{m['name']}: {m['crossings']} cr.\n{table}\nE {m['energy']:.3f}, 3D {m['threedim']:.2f}, "
                      f"sim {m['similarity']:.2f}\n{circles(m)}", None))
for block, items in enumerate((top, bottom)):
    for col in range(cols):
        for k, view in enumerate(("top", "front")):
            ax = axs[2 * block + k][col]
            if col >= len(items):
                ax.axis("off")
                continue
            P, label, fr = items[col]
            if block == 0 and col > 0:
                draw_framed(ax, pattern, view, frame, radius=radius, color="0.8")
            draw_framed(ax, P, view, fr, radius=radius)
            if k == 0:
                ax.set_title(label, fontsize=5.5)
axs[0][0].set_ylabel("top", fontsize=7)
axs[1][0].set_ylabel("front", fontsize=7)
axs[2][0].set_ylabel("top", fontsize=7)
axs[3][0].set_ylabel("front", fontsize=7)
fig.suptitle(f"three intertwined circles: 9_35 and its closest states in {s['dataset']} (top; "
             f"{s['dataset_three_circle_states']} of {s['dataset_equilibria']} data-set states fit three circles), "
             f"pretzel knots built beyond the table (bottom)", fontsize=8)
save(fig, a.out, "fig15_generalization")
