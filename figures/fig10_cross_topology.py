"""Fig. 10: cross-topology analysis. For each query state (left), the
equilibria of other knot types in the data set closest in shape (ICP
alignment after a pre-filter on 3D-ness and diameter), ranked, each drawn
aligned onto the query and in the query's frame, with its alignment distance."""
from common import dataset_material, draw_framed, frame_of, parse_args, plt, read_obj, read_summary, save

a = parse_args(__doc__)
s = read_summary(a.results, "cross_topology")
radius, _ = dataset_material(f"{a.results}/{s['dataset']}")
queries = s["queries"]
cols = 1 + max((len(q["hits"]) for q in queries), default=0)
fig, axs = plt.subplots(2 * len(queries), cols, figsize=(1.6 * cols, 3.4 * len(queries)), squeeze=False)
for row, q in enumerate(queries):
    Q = read_obj(f"{a.results}/cross_topology/{q['curve']}")
    frame = frame_of(Q)
    curves = [(Q, f"query {q['knot']} #{q['equilibrium']}\n3D-ness {q['threedim']:.2f}")]
    curves += [(read_obj(f"{a.results}/cross_topology/{h['curve']}"),
                f"{h['rank']}. {h['knot']} #{h['index']}\nd = {h['distance']:.2f}") for h in q["hits"]]
    for col in range(cols):
        for k, view in enumerate(("top", "front")):
            ax = axs[2 * row + k][col]
            if col >= len(curves):
                ax.axis("off")
                continue
            if col > 0:  # the query in grey behind each hit
                draw_framed(ax, Q, view, frame, radius=radius, color="0.8")
            draw_framed(ax, curves[col][0], view, frame, radius=radius)
            if k == 0:
                ax.set_title(curves[col][1], fontsize=6)
    axs[2 * row][0].set_ylabel("top", fontsize=7)
    axs[2 * row + 1][0].set_ylabel("front", fontsize=7)
fig.suptitle(f"cross-topology search: the closest equilibria of other knot types ({s['dataset']}; "
             f"alignment distance in edge lengths; grey: the query)", fontsize=9)
save(fig, a.out, "fig10_cross_topology")
