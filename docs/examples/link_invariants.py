"""The invariants of a link of the link table, laid out from its braid, as
examples/link_invariants.cpp computes them: each component's Alexander
polynomial and writhe, the linking numbers (exact Gauss sums) and the Conway
polynomial, checked against the table; then the link relaxed, its linking
numbers unchanged.

    python3 docs/examples/link_invariants.py [LINK]     (default borromean)
"""
import sys

import numpy as np

import elastic_knots as ek

name = sys.argv[1] if len(sys.argv) > 1 else "borromean"
table = ek.knot(name)  # a link of the link table: components, linking_numbers, conway, ...
drawn = ek.embed(name, vertices=240)
print(f"{name}: {drawn.components} components, {drawn.vertices} vertices, Conway {drawn.conway}")
for c, P in enumerate(drawn.points):
    print(f"  component {c}: Alexander {ek.alexander(P)}, writhe {ek.writhe(P):.3f}")
m = len(drawn.points)
lk = np.array([[0 if i == j else round(ek.linking_number(drawn.points[i], drawn.points[j])) for j in range(m)]
               for i in range(m)])
print("  linking numbers\n", lk)
assert lk.tolist() == drawn.linking_numbers == table.linking_numbers, "the linking numbers differ from the table"
assert drawn.conway == table.conway, "the Conway polynomial differs from the table"
r = ek.relax_link(drawn.points)
print(f"  relaxed: {r.status}, energy {r.energy:.4f}, linking numbers {r.linking_numbers}")
assert r.linking_numbers == table.linking_numbers
print("  as the link table says")
