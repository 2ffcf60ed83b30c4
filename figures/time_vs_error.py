"""Run time against error (issue 11; `make bench`): the k-covered circle, the
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

ax = axs[1]
for name in sorted({r["knot"] for r in knots}):
    rows = [r for r in knots if r["knot"] == name and float(r["relative_error"]) > 0]
    ax.loglog([float(r["seconds"]) for r in rows], [float(r["relative_error"]) for r in rows], "o-", label=name)
    for r in rows:
        ax.annotate(r["n"], (float(r["seconds"]), float(r["relative_error"])), fontsize=6)
ax.set_xlabel("time per equilibrium [s] (one core)")
ax.set_ylabel("relative energy error (Richardson reference)")
ax.set_title("knots: resolution n")
ax.legend(fontsize=7)

ax = axs[2]
for name in sorted({r["knot"] for r in tol}):
    rows = [r for r in tol if r["knot"] == name]
    ax.loglog([float(r["seconds"]) for r in rows], [max(float(r["relative_error"]), 1e-17) for r in rows], "o-",
              label=name)
    for r in rows:
        ax.annotate(r["tolerance"], (float(r["seconds"]), max(float(r["relative_error"]), 1e-17)), fontsize=6)
ax.set_xlabel("time per equilibrium [s] (one core)")
ax.set_ylabel("relative energy error (tolerance 1e-12 reference)")
ax.set_title("knots: gradient tolerance, n = 400")
ax.legend(fontsize=7)
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
