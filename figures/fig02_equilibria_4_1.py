"""Fig. 2: the distinct equilibria of the figure-eight knot 4_1 sorted by
elastic energy, each as three orthogonal shadows coloured by curvature."""
from common import draw_distinct_equilibria, parse_args

draw_distinct_equilibria(parse_args(__doc__), "4_1", "fig02_equilibria_4_1")
