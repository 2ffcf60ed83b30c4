"""The periodic braids' members whose closure is a link (beyond Fig. 16,
which shows knots; paper Section 8.5: links): each relaxed as a link from
the coil, one colour per component, seen along its axis of least extent and
from the side, with its p-fold symmetry error beside the (p+1)-fold control."""
from common import need, parse_args, plt, read_summary, save, save_empty
from common import read_link
from render import draw_link

COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red")

a = parse_args(__doc__)
s = read_summary(a.results, "periodic_braids")
links = s["links"]
if not links:
    save_empty(a.out, "fig16_links", "no periodic braid closes into a link")
    raise SystemExit
fig, axs = plt.subplots(2, len(links), figsize=(2.6 * len(links), 5.2), squeeze=False)
for k, m in enumerate(links):
    components = read_link(need(f"{a.results}/periodic_braids/{m['curve']}"))
    colours = [COLOURS[c % len(COLOURS)] for c in range(len(components))]
    for row, view in enumerate(("top", "front")):
        draw_link(axs[row][k], components, radius=s["radius"], colors=colours, view=view)
    word = "(σ1σ2⁻¹)" if m["family"] == "s1s2i" else "(σ1σ2⁻¹σ3)"
    axs[0][k].set_title(f"{word}^{m['p']}: {m['components']} components\n{m['status']}, 3D-ness {m['threedim']:.2f}\n"
                        f"{m['p']}-fold error {m['symmetry_error']:.2g} (control {m['control_error']:.2g})",
                        fontsize=7)
fig.suptitle("periodic braids closing into links, relaxed as links (top: along the axis of least extent)",
             fontsize=9)
save(fig, a.out, "fig16_links")
