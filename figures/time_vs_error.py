"""Run time against error (`make bench`; docs/performance.md): the k-covered circle, the
critical link of Michell's instability, knot equilibria at several n against
a Richardson reference, and the solver tolerance sweep. Reads
results/bench/time_vs_error/*.csv (exp_time_vs_error); prints the table."""
import argparse
import os

from common import plt, read_csv, save

p = argparse.ArgumentParser(description=__doc__)
p.add_argument("--results", default="results/bench/time_vs_error")
p.add_argument("--out", default="figures/out")
a = p.parse_args()
os.makedirs(a.out, exist_ok=True)

circles = read_csv(f"{a.results}/circles.csv")
michell = read_csv(f"{a.results}/michell.csv")
knots = read_csv(f"{a.results}/knots.csv")
tol = read_csv(f"{a.results}/tolerance.csv")

fig, axs = plt.subplots(1, 3, figsize=(15, 4.5))
fig.subplots_adjust(wspace=0.35)
ax = axs[0]
for k in ("1", "2", "3"):
    rows = [r for r in circles if r["k"] == k]
    ax.loglog([int(r["n"]) for r in rows], [float(r["relative_error"]) for r in rows], "o-",
              label=f"{k}-covered circle, bending energy ({rows[0]['how']})")
ax.loglog([int(r["n"]) for r in michell], [float(r["relative_error"]) for r in michell], "s-",
          label="Michell critical link √3(1+ν)")
ax.set_xlabel("vertices n")
ax.set_ylabel("relative error")
ax.set_title("exact answers")
ax.legend(fontsize=7)

def time_error_panel(ax, rows, label_key, ylabel, title):
    """Time per equilibrium against relative energy error, one line per knot,
    each point annotated with its rows' label_key (n or tolerance)."""
    for name in sorted({r["knot"] for r in rows}):
        sel = [r for r in rows if r["knot"] == name]
        x = [float(r["seconds"]) for r in sel]
        y = [max(float(r["relative_error"]), 1e-17) for r in sel]
        ax.loglog(x, y, "o-", label=name)
        for r, xi, yi in zip(sel, x, y):
            ax.annotate(r[label_key], (xi, yi), fontsize=6)
    ax.set_xlabel("time per equilibrium [s] (one core)")
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.legend(fontsize=7)


time_error_panel(axs[1], [r for r in knots if float(r["relative_error"]) > 0], "n",
                 "relative energy error (Richardson reference)", "knots: resolution n")
time_error_panel(axs[2], tol, "tolerance", "relative energy error (tolerance 1e-12 reference)",
                 "knots: gradient tolerance, n = 400")
save(fig, a.out, "time_vs_error")

print(f"{'case':<28}{'n / tol':>10}{'rel. error':>12}{'seconds':>10}")
for r in circles:
    print(f"{r['k'] + '-covered circle':<28}{r['n']:>10}{float(r['relative_error']):>12.2e}{float(r['seconds']):>10.4f}")
for r in michell:
    print(f"{'Michell Lk_c':<28}{r['n']:>10}{float(r['relative_error']):>12.2e}{float(r['seconds']):>10.4f}")
for r in knots:
    print(f"{r['knot'] + ' resolution':<28}{r['n']:>10}{float(r['relative_error']):>12.2e}{float(r['seconds']):>10.4f}")
for r in tol:
    print(f"{r['knot'] + ' tolerance':<28}{r['tolerance']:>10}{float(r['relative_error']):>12.2e}{float(r['seconds']):>10.4f}")
