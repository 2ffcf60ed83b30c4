# Elastic knots: the two commands a new user needs are `make test` and
# `make figures`; every target is listed by `make help` and in docs/reproducing.md.

BUILD      ?= build
JOBS       ?= 2
KNOT_TABLE ?= $(abspath $(CURDIR)/../shared/data/knotinfo_table.csv)
PEER_DATA  ?= $(abspath $(CURDIR)/../shared/data/peer)
SCALE      ?= default
PYTHON     ?= /usr/bin/python3
CMAKE_ARGS ?=

CONFIGURE = cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DEK_KNOT_TABLE=$(KNOT_TABLE) \
            -DPython3_EXECUTABLE=$(PYTHON) $(CMAKE_ARGS)
CTEST     = cd $(BUILD) && KNOT_TABLE=$(KNOT_TABLE) ctest --output-on-failure -j$(JOBS)

.PHONY: animation ledger-results ledger-shards ledger-far-end stopping-truth help help-experiments deps docs configure build python test unit sanitize fuzz fuzz-build fuzz-test fuzz-seeds stress slurm-test bench figures experiments studies claims paper-open manifest compare-methods clean \
        explorer explorer-screenshots serve browser

help:
	@echo "make test      build, run all tests (unit, parsers, short stress, paper claims at ci scale, Python module, Slurm, sanitizers, fuzz corpus + 20 s per fuzz target) and the API reference (make docs, no warning)"
	@echo "make figures   build, run every experiment at SCALE=$(SCALE), write figures/out/*.png|pdf"
	@echo "make experiment-NAME   run one experiment (NAME: $(PAPER_EXPERIMENTS) $(STUDY_EXPERIMENTS) $(BENCH_EXPERIMENTS))"
	@echo "make help-experiments  each experiment's inputs and run time per scale (experiments/manifest.json)"
	@echo "make claims    the paper checks on the results of SCALE (make figures ends with it; docs/reproducing.md)"
	@echo "make studies   the studies beside the paper (the periodic braids' link scan) at SCALE, and their checks"
	@echo "make paper-open  the claims not reproduced (paper_checks/open_claims.cpp), values printed"
	@echo "make ledger-shards SCALE=sample12|paper10  run the scale shard by shard, committing each finished shard's ledger"
	@echo "make stopping-truth  both adaptive stopping rules replayed on 30 knots of 500 samples each (docs/results/truth/)"
	@echo "make ledger-far-end SCALE=sample12|paper10  Fig. 9's far end decided at the full budget: the knots it needs sampled 500 times, each piece's ledger committed"
	@echo "make ledger-results  Fig. 9, planarity and the sampling summary of the committed ledgers (docs/results/), and their checks"
	@echo "make compare-methods  the default relaxation method against METHOD=$(METHOD) (the direct one, hybrid, unless given) on the SCALE data sets"
	@echo "make animation the jumping knot's release in time as figures/out/anim_jumping_dynamics.gif and .mp4 (runs exp_jumping_dynamics at SCALE if needed)"
	@echo "make explorer  the data-set explorer of SCALE's data set in results/<scale>/explorer/ (docs/explorer.md)"
	@echo "make serve     serve that data set's explorer on 127.0.0.1:8000"
	@echo "make explorer-screenshots  screenshots of its views and its load time in headless Chromium"
	@echo "make browser   the explorer's browser tests (label browser, also in make test)"
	@echo "make bench     Google Benchmark microbenchmarks and macro benchmarks (results/bench/; docs/performance.md)"
	@echo "make stress    the long numerical stress tests (label stress-long)"
	@echo "make sanitize  parsers and readers built and tested with AddressSanitizer and UBSan"
	@echo "make slurm-test  the data set as a Slurm job array on a single-host Slurm (docs/cluster.md; root)"
	@echo "make fuzz      libFuzzer on every reader, FUZZ_SECONDS=$(FUZZ_SECONDS) per target; crash inputs in results/fuzz/"
	@echo "make unit      unit tests only"
	@echo "make python    the Python module elastic_knots in $(BUILD)/python (docs/python.md)"
	@echo "make docs      the API reference of the public headers (Doxygen) in $(BUILD)/docs/html; fails on any warning"
	@echo "make deps      install missing Debian packages (scripts/install-deps.sh)"
	@echo "make manifest  regenerate experiments/manifest.mk from experiments/manifest.json"
	@echo "make clean     remove build folders (results/ and figures/out/ are kept)"
	@echo "Variables: KNOT_TABLE=$(KNOT_TABLE) SCALE=ci|default|paper|paper10|sample12 JOBS=$(JOBS) BUILD=$(BUILD) FUZZ_SECONDS=$(FUZZ_SECONDS)"
	@echo "Documentation: README.md; docs/reproducing.md (targets, scales, claims), docs/cli.md (knots),"
	@echo "  docs/models.md, docs/performance.md, docs/dataset-format.md, docs/results.md (results files),"
	@echo "  docs/cluster.md (Slurm), docs/explorer.md (the data-set explorer)"

deps:
	@scripts/install-deps.sh

# The API reference (docs/api/Doxyfile: the public headers and the pages of
# docs/api/) in $(BUILD)/docs/html. Every Doxygen warning (an undocumented
# public declaration, a malformed command) fails the target; the warnings are
# printed from $(BUILD)/docs/warnings.log, each once (Doxygen reports a free
# function's twice: in its file and in its namespace).
EK_VERSION = $(shell sed -n 's/^project.elastic_knots VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
docs: deps
	@rm -rf $(BUILD)/docs/html && mkdir -p $(BUILD)/docs
	@( cat docs/api/Doxyfile; \
	   echo 'OUTPUT_DIRECTORY = "$(BUILD)/docs"'; \
	   echo 'WARN_LOGFILE = "$(BUILD)/docs/warnings.log"'; \
	   echo 'PROJECT_NUMBER = $(EK_VERSION)' ) | doxygen - ; status=$$?; \
	if [ $$status -ne 0 ] || [ -s $(BUILD)/docs/warnings.log ]; then \
	  awk '!seen[$$0]++' $(BUILD)/docs/warnings.log >&2; \
	  echo "make docs: $$(sort -u $(BUILD)/docs/warnings.log | grep -c .) Doxygen warnings (doxygen exit status $$status)" >&2; \
	  exit 1; fi
	@echo "API reference: $(BUILD)/docs/html/index.html"

configure: deps
	@$(CONFIGURE) > /dev/null

build: configure
	cmake --build $(BUILD) -j$(JOBS)

python: configure
	cmake --build $(BUILD) -j$(JOBS) --target elastic_knots

test: build fuzz-build docs
	cd $(BUILD)-fuzz && KNOT_TABLE=$(KNOT_TABLE) ctest --output-on-failure -j$(JOBS) -L 'parsers|fuzz'
	$(CTEST) -LE 'stress-long|sanitize|paper-open'

unit: build
	$(CTEST) -L 'unit|parsers'

browser: build
	$(CTEST) -L browser

# The parsers' and readers' tests (label parsers) with AddressSanitizer and
# UBSan, in the Clang build of the fuzz targets below (one build serves both).
sanitize: fuzz-build
	cd $(BUILD)-fuzz && KNOT_TABLE=$(KNOT_TABLE) ctest --output-on-failure -j$(JOBS) -L parsers

# The data set as a Slurm job array (scripts/slurm/) on a single-host Slurm
# that the test starts and stops itself (tests/slurm/; docs/cluster.md).
slurm-test: configure
	cmake --build $(BUILD) -j$(JOBS) --target knots
	$(CTEST) -L slurm

# libFuzzer targets of the readers (tests/fuzz/) and the parsers' tests:
# Clang with ASan and UBSan, parsers-only modules, in $(BUILD)-fuzz. `make
# fuzz` runs each target for FUZZ_SECONDS ($(JOBS) at a time) and fails on any
# crash (its input is left in results/fuzz/TARGET/); `make test` runs the
# parsers' tests, replays the seed corpus and runs each target for 20 s
# (CTest labels parsers and fuzz).
FUZZ_SECONDS ?= 300
fuzz-build: deps
	@cmake -S . -B $(BUILD)-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
	  -DCMAKE_C_FLAGS=-O1 -DCMAKE_CXX_FLAGS=-O1 -DEK_FUZZ=ON -DEK_PARSERS_ONLY=ON -DEK_BUILD_TESTS=ON \
	  -DEK_KNOT_TABLE=$(KNOT_TABLE) > /dev/null
	cmake --build $(BUILD)-fuzz -j$(JOBS)

fuzz: fuzz-build
	$(PYTHON) tests/fuzz/run_fuzz.py --build $(BUILD)-fuzz --results results/fuzz --seconds $(FUZZ_SECONDS) --jobs $(JOBS)

fuzz-test: fuzz-build
	cd $(BUILD)-fuzz && ctest --output-on-failure -j$(JOBS) -L fuzz

# Rewrites the binary seeds (data sets, journals) of tests/fuzz/corpus/.
fuzz-seeds: fuzz-build
	$(BUILD)-fuzz/tests/fuzz/fuzz_make_seeds tests/fuzz/corpus

# Prints the counts of every stress test (-V) and keeps one CSV row per run
# of the 10,000-sample volume in results/stress/volume.csv.
stress: build
	@mkdir -p results/stress
	cd $(BUILD) && KNOT_TABLE=$(KNOT_TABLE) EK_STRESS_LOG=$(CURDIR)/results/stress/volume.csv \
	  ctest -V -j$(JOBS) -L 'stress'

# Microbenchmarks pinned to one core (Google Benchmark, median of 5), then the
# macro benchmarks (the solver's default method against hybrid-simplicial, the
# direct method with CHOLMOD's simplicial factorisation, interleaved: the lattice
# samples, the peer curves and the cost against n; the skips; time against
# error); one summary table at the end.
BENCH_CORE ?= 0
# exp_time_vs_error: ci (n <= 800) or default (n <= 3200)
BENCH_SCALE ?= default
bench: build
	cmake --build $(BUILD) -j$(JOBS) --target bench_programs
	@mkdir -p results/bench
	@for b in $(BUILD)/bench/bench_*; do \
	  [ -x "$$b" ] || continue; \
	  echo "== $$b"; \
	  taskset -c $(BENCH_CORE) $$b --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
	    --benchmark_out=results/bench/$$(basename $$b).json --benchmark_out_format=json || exit 1; \
	done
	@if [ -x $(BUILD)/experiments/exp_bench_solver ]; then \
	  taskset -c $(BENCH_CORE) $(BUILD)/experiments/exp_bench_solver --methods default,hybrid-simplicial --out results/bench && \
	  taskset -c $(BENCH_CORE) $(BUILD)/experiments/exp_bench_solver --methods default,hybrid-simplicial \
	    --peer $(PEER_DATA) --out results/bench && \
	  taskset -c $(BENCH_CORE) $(BUILD)/experiments/exp_bench_solver --methods default,hybrid-simplicial --scaling \
	    --out results/bench && \
	  taskset -c $(BENCH_CORE) $(BUILD)/experiments/exp_bench_solver --skips --count 3 \
	    --knots 4_1,8_19,12a_1019 --out results/bench; fi
	@if [ -x $(BUILD)/experiments/exp_bench_saddles ]; then \
	  taskset -c $(BENCH_CORE) $(BUILD)/experiments/exp_bench_saddles --out results/bench; fi
	taskset -c $(BENCH_CORE) $(BUILD)/experiments/exp_time_vs_error --scale $(BENCH_SCALE) --out results/bench/time_vs_error
	PYTHONPATH=$(BUILD)/python $(PYTHON) bench/python_thread_pool.py --out results/bench
	MPLBACKEND=Agg $(PYTHON) figures/time_vs_error.py --results results/bench/time_vs_error --out figures/out
	@$(PYTHON) scripts/bench_summary.py results/bench

# ---- paper experiments and figures -------------------------------------------
# make experiment-NAME [SCALE=ci|default|paper|paper10|sample12] runs one experiment (always);
# make figures runs every experiment whose results are missing or older than
# its program (and inputs), then draws every figure from the results files.
# The experiments, their inputs and figures: experiments/manifest.json, from
# which scripts/manifest.py generates experiments/manifest.mk (make manifest).
RESULTS     = results/$(SCALE)
EXP         = $(BUILD)/experiments
include experiments/manifest.mk
FIGURES     = $(patsubst %,figures/out/%.png,$(PAPER_FIGURES))

# At the paper scale exp_adaptive replays the ground truth of the stopping
# rules (make stopping-truth) instead of relaxing every knot 500 times.
TRUTH_DATASET = results/truth/truth.h5
ARGS_adaptive_paper = --fixed $(TRUTH_DATASET)

$(RESULTS)/%/summary.json: $(EXP)/exp_%
	$(EXP)/exp_$* --scale $(SCALE) --out $(RESULTS)/$* --jobs $(JOBS) $(ARGS_$*_$(SCALE))

experiment-%: build
	$(EXP)/exp_$* --scale $(SCALE) --out $(RESULTS)/$* --jobs $(JOBS) $(ARGS_$*_$(SCALE))

experiments: build
	@$(MAKE) --no-print-directory $(foreach e,$(PAPER_EXPERIMENTS),$(RESULTS)/$(e)/summary.json)

# The studies beside the paper (group study in experiments/manifest.json: the
# periodic braids' link scan), at SCALE, then their checks (label study).
studies: build
	@$(MAKE) --no-print-directory $(foreach e,$(STUDY_EXPERIMENTS),$(RESULTS)/$(e)/summary.json)
	cd $(BUILD) && EK_PAPER_RESULTS=$(abspath $(RESULTS)) KNOT_TABLE=$(KNOT_TABLE) \
	  ctest --output-on-failure -L '^study$$' -E '^paper_run_' -FS '.*'

figures: deps experiments
	@mkdir -p figures/out
	@$(MAKE) --no-print-directory $(FIGURES)
	@$(MAKE) --no-print-directory claims

# The paper checks (label paper) on the results of SCALE, without rerunning
# the ci fixtures; `make figures` ends with it. The figure scripts' tests
# (figure_*, label paper) draw the ci results in `make test`; at SCALE
# `make figures` has drawn them already, so they are left out here.
claims: build
	cd $(BUILD) && EK_PAPER_RESULTS=$(abspath $(RESULTS)) KNOT_TABLE=$(KNOT_TABLE) \
	  ctest --output-on-failure -L '^paper$$' -E '^(paper_run_|figure_)' -FS '.*'
	@echo "== claims not reproduced (paper_checks/open_claims.cpp), measured at SCALE=$(SCALE):"
	-@cd $(BUILD) && EK_PAPER_RESULTS=$(abspath $(RESULTS)) $(abspath $(BUILD))/paper_checks/paper_checks \
	  --gtest_filter='PaperOpen*' | grep -E 'measured|OK|FAILED' || true

# The claims this project does not reproduce (paper_checks/open_claims.cpp),
# after every experiment at the ci scale; expected to fail, prints the values.
paper-open: build
	$(CTEST) -L 'paper'

# (each figure's experiment summary is a prerequisite: experiments/manifest.mk)
figures/out/%.png: figures/%.py figures/common.py figures/render.py
	MPLBACKEND=Agg $(PYTHON) $< --results $(RESULTS) --out figures/out

# The jumping knot's frictionless release as an animation (tubes rendered by
# POV-Ray, assembled by ffmpeg) from SCALE's jumping_dynamics results.
animation: deps $(RESULTS)/jumping_dynamics/summary.json
	@mkdir -p figures/out
	$(PYTHON) figures/anim_jumping_dynamics.py --results $(RESULTS) --out figures/out

# ---- the data-set explorer (docs/explorer.md) ------------------------------------
EXPLORER_DATASET ?= $(RESULTS)/dataset/dataset.h5
PORT             ?= 8000

explorer: build
	$(BUILD)/bin/knots site $(EXPLORER_DATASET) -o $(RESULTS)/explorer --overwrite

serve: build
	$(BUILD)/bin/knots serve $(EXPLORER_DATASET) --port $(PORT)

explorer-screenshots: explorer
	$(PYTHON) scripts/explorer_screenshots.py --site $(RESULTS)/explorer --out $(RESULTS)/screenshots

manifest:
	$(PYTHON) scripts/manifest.py

# ---- the committed paper-scale results (docs/reproducing.md, "The ledgers") ----
# ledger-shards: the paper-scale data set of SCALE (sample12 or paper10) shard
# by shard in the background at the lowest priority, each finished shard's
# ledger committed under docs/results/SCALE/ledgers/ (scripts/ledger_shards.sh;
# progress in results/SCALE/shards/progress.log). ledger-results: those
# ledgers analysed again without any relaxation: the sampling summary
# (knots describe --summary), exp_milnor and exp_planarity, Fig. 9, the
# planarity histogram and one knot's state gallery (fig_ledger_states.py:
# 8_1 for paper10, 12a_81 for sample12), and the data-set claims PaperMilnor.* and
# PaperPlanarity.* checked on them, for every scale that has ledgers.
LEDGER_SCALES ?= sample12 paper10
ledger-shards: build
	scripts/ledger_shards.sh $(SCALE) --commit --nice

# ledger-far-end: Fig. 9's far end at the full budget (scripts/ledger_far_end.sh
# SCALE --until-decided): the knots exp_milnor names (far_end_to_sample) sampled
# again with 500 samples each, a few knots per piece of about 15 minutes,
# each piece's ledger committed under docs/results/SCALE/full_budget/, round
# after round until it names none (progress in results/SCALE/full_budget/progress.log).
ledger-far-end: build
	scripts/ledger_far_end.sh $(SCALE) --until-decided --commit --nice

# stopping-truth: the ground truth of the stopping rules (scripts/ledger_shards.sh
# truth: 30 knots of 5 to 12 crossings, 500 samples each, about 1 h on 2
# cores; its ledgers committed under docs/results/truth/ledgers/), its
# shards merged into $(TRUTH_DATASET), both stopping rules replayed on it
# (exp_adaptive at the paper scale, docs/results/truth/adaptive/) and checked.
stopping-truth: build
	scripts/ledger_shards.sh truth --commit --nice --datasets
	@if [ ! -f $(TRUTH_DATASET) ]; then \
	  $(BUILD)/bin/knots merge results/truth/shards/shard-*-of-04.h5 -o $(TRUTH_DATASET); fi
	$(EXP)/exp_adaptive --scale paper --fixed $(TRUTH_DATASET) --out docs/results/truth/adaptive --jobs $(JOBS)
	EK_PAPER_RESULTS=$(CURDIR)/docs/results/truth KNOT_TABLE=$(KNOT_TABLE) $(BUILD)/paper_checks/paper_checks \
	  --gtest_filter='StoppingRules.*'

ledger-results: build
	@for s in $(LEDGER_SCALES); do \
	  d=docs/results/$$s; \
	  if ! ls $$d/ledgers/*.ledger.h5 > /dev/null 2>&1; then echo "== $$s: no ledgers yet"; continue; fi; \
	  echo "== $$s: $$(ls $$d/ledgers/*.ledger.h5 | wc -l) ledgers"; \
	  $(BUILD)/bin/knots describe $$d/ledgers --summary > $$d/ledgers_summary.json.part && \
	    mv $$d/ledgers_summary.json.part $$d/ledgers_summary.json && \
	  $(EXP)/exp_milnor --scale $$s --out $$d/milnor && \
	  $(EXP)/exp_planarity --scale $$s --out $$d/planarity && \
	  MPLBACKEND=Agg $(PYTHON) figures/fig09_milnor.py --results $$d --out $$d && \
	  MPLBACKEND=Agg $(PYTHON) figures/fig_planarity.py --results $$d --out $$d && \
	  MPLBACKEND=Agg $(PYTHON) figures/fig_ledger_states.py --results $$d --knot $$(case $$s in paper10) echo 8_1;; *) echo 12a_81;; esac) --out $$d && \
	  EK_PAPER_RESULTS=$(CURDIR)/$$d KNOT_TABLE=$(KNOT_TABLE) $(BUILD)/paper_checks/paper_checks \
	    --gtest_filter='PaperMilnor.*:PaperPlanarity.*' || exit 1; \
	done

# The default relaxation method (multilevel) against another named method
# (METHOD=hybrid, the direct one, unless given; eigen-projected, exact, paper): both
# methods' data sets and their paper checks, then their comparison
# (docs/reproducing.md). SCALE=default by default; SCALE=ci is a smoke run.
METHOD ?= hybrid
compare-methods: build
	scripts/compare_methods.sh $(BUILD) $(SCALE) $(RESULTS) $(JOBS) $(KNOT_TABLE) $(METHOD)

help-experiments:
	@$(foreach e,$(PAPER_EXPERIMENTS) $(STUDY_EXPERIMENTS) $(BENCH_EXPERIMENTS),echo "$(e): minutes $(MINUTES_$(e))";)
	@echo "(inputs, outputs, figures and checks: experiments/manifest.json)"

clean:
	rm -rf $(BUILD) $(BUILD)-asan $(BUILD)-fuzz
