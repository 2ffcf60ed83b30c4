"""Fig. 7: filters (paper Section 7.3). For each attribute, the equilibria of
the data set with the smallest (upper block) and the largest value (lower
block), each from three sides as a tube coloured by curvature, with the value
and the knot type."""
from common import dataset_material, draw_views, parse_args, plt, read_obj, read_summary, save

LABELS = {"energy": "energy", "stiffness": "stiffness", "max_stress": "max. stress",
          "total_curvature": "total curvature", "threedim": "3D-ness", "sphericity": "sphericity",
          "diameter": "diameter"}

a = parse_args(__doc__)
s = read_summary(a.results, "filters")
radius, _ = dataset_material(f"{a.results}/{s['dataset']}")
attributes = s["attributes"]
by = {(x["attribute"], x["extreme"]): x for x in s["extremes"]}
fig, axs = plt.subplots(6, len(attributes), figsize=(1.6 * len(attributes), 7.6), squeeze=False)
for col, attribute in enumerate(attributes):
    for block, extreme in enumerate(("min", "max")):
        x = by[(attribute, extreme)]
        cells = [axs[3 * block + k][col] for k in range(3)]
        draw_views(cells, read_obj(f"{a.results}/filters/{x['curve']}"), views=("top", "front", "side"), radius=radius, radius_scale=4.0)
        for c in cells:
            c.set_title("")
        head = f"{LABELS.get(attribute, attribute)}\n" if block == 0 else ""
        cells[0].set_title(f"{head}{extreme} {x['value']:.4g}\n{x['knot']} #{x['index']}", fontsize=6)
for block, extreme in enumerate(("smallest", "largest")):
    for k, view in enumerate(("top", "front", "side")):
        axs[3 * block + k][0].set_ylabel(f"{extreme}\n{view}" if k == 0 else view, fontsize=7)
fig.suptitle(f"filters: extremes of each attribute over {s['equilibria']} equilibria of {s['knots']} knot types "
             f"(colour: curvature)", fontsize=9)
save(fig, a.out, "fig07_filters")
