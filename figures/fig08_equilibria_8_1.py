"""Fig. 8: the distinct equilibria of 8_1 sorted by elastic energy, each as
three orthogonal shadows coloured by curvature."""
from common import draw_distinct_equilibria, parse_args

draw_distinct_equilibria(parse_args(__doc__), "8_1", "fig08_equilibria_8_1")
