# Dynamics textbook: `make book` builds the site, `make test` checks everything.
# Both create .venv and install requirements.txt on first use.

SHELL := /bin/bash
.SHELLFLAGS := -eo pipefail -c      # a failure inside a pipe fails the target
PYTHON ?= python3
VENV   ?= .venv
BIN    := $(VENV)/bin
SITE   := _build/html
PORT   ?= 8000

# Reproducible figures: matplotlib stamps SVG/PDF with this date instead of "now".
export SOURCE_DATE_EPOCH ?= 1767225600
export FORCE_SOURCE_DATE := 1
export PYTHONHASHSEED := 0
# Python keeps its bytecode (__pycache__, ignored by git), and pytest its rewritten test
# modules: a machine that sets PYTHONDONTWRITEBYTECODE would compile the book's code and
# the tests again in every process (about 7 s of each pytest start).
unexport PYTHONDONTWRITEBYTECODE

# Strict: any warning, broken reference or cell error fails the build.
JB_BUILD := $(BIN)/jupyter-book build . -n -W --keep-going

.PHONY: help venv html book test check serve clean lint

help:
	@echo "make book   build the site into $(SITE), with its PDFs (make html: HTML only)"
	@echo "make test   build the site, then run the whole test suite (what CI runs)"
	@echo "make check  ruff, ESLint, Prettier + the tests that need no build or browser (under a minute)"
	@echo "make pdf    build the PDF book, question sheet and answer key into $(PDF)"
	@echo "make worksheets  the teachers' worksheets (versions A-C with keys); make moodle: the Moodle XML"
	@echo "make serve  serve the built site on http://localhost:$(PORT)"
	@echo "make lint   ruff over the Python code, ESLint and Prettier over the JavaScript"
	@echo "make lock   rewrite requirements.txt (the lock, with hashes) from pyproject.toml"
	@echo "make bench  time cold/no-op/one-edit builds, weigh every page, Lighthouse: BENCHMARKS.md"
	@echo "make clean  remove the build (keeps .venv)"

venv: $(VENV)/.installed

# Re-install whenever the lock or the package metadata change. requirements.txt is the lock
# (every package pinned, with hashes; make lock writes it from pyproject.toml). pip installs uv,
# the lock's own pinned entry (its lines up to the last hash), then uv installs the whole lock,
# checking each download against its hash: seconds, where pip takes a minute. The book's own
# package goes in last, editable, without its dependencies (they are in the lock) and built by
# the locked setuptools, not a fresh download.
UV_ENTRY := awk '/^uv==/ { entry = 1 } entry { print; if (!/\\$$/) exit }' requirements.txt
$(VENV)/.installed: requirements.txt pyproject.toml
	@test -x $(BIN)/python || { echo ">>> creating $(VENV)"; $(PYTHON) -m venv $(VENV); }
	@echo ">>> installing requirements into $(VENV)"
	$(BIN)/python -m pip install --quiet --require-hashes --no-deps -r <($(UV_ENTRY))
	$(BIN)/uv pip install --quiet --require-hashes --python $(BIN)/python -r requirements.txt
	$(BIN)/uv pip install --quiet --no-deps --no-build-isolation --python $(BIN)/python -e .
	$(BIN)/python -m ipykernel install --sys-prefix --name python3 --display-name "Python 3" >/dev/null
	@touch $@

# The lock: pyproject.toml declares the dependencies (direct ones pinned), pip-compile (pip-tools,
# itself in the lock) resolves every transitive package and pins it with its hashes. Pins already
# in requirements.txt are kept; to move one: make lock LOCK_ARGS="--upgrade-package NAME".
# tests/no_site/test_lock.py checks that the two agree (make check: offline; make test: runs this target
# into a temporary file and compares).
LOCK_OUT ?= requirements.txt
LOCK_ARGS ?=
.PHONY: lock
lock: venv
	@echo ">>> locking pyproject.toml's dependencies into $(LOCK_OUT)"
	$(BIN)/pip-compile --quiet --generate-hashes --allow-unsafe --strip-extras --all-extras \
	  --no-emit-index-url --no-emit-find-links $(LOCK_ARGS) --output-file=$(LOCK_OUT) pyproject.toml

# Node tools: MathJax renders the maths at build time; axe-core and Lighthouse test the site.
# Debian's nodejs package carries no npm, hence the second package.
node_modules/.package-lock.json: package.json package-lock.json
	@scripts/ensure-debian-packages html
	@echo ">>> installing the node tools (npm ci)"
	npm ci --no-audit --no-fund --loglevel=error
	@touch $@

html: venv node_modules/.package-lock.json
	@echo ">>> building the HTML site (pages are executed; cached pages are reused)"
	$(JB_BUILD)

# The site links the teachers' PDFs, worksheets and Moodle file, and a zip of itself (to
# read from disk, offline), so the book is the HTML, then the PDFs, the worksheets and the
# Moodle XML side by side (each writes its own files; each one's output is printed when it
# is done), then the zip of all.
book: html
	@scripts/ensure-debian-packages pdf
	@echo ">>> the PDFs, the teachers' worksheets and the Moodle XML, side by side"
	@$(MAKE) --no-print-directory -j3 --output-sync=target pdf worksheets moodle
	@echo ">>> packing the site into a zip to open from disk"
	$(BIN)/python scripts/zip_site.py $(SITE)
	@echo ">>> done: open $(CURDIR)/$(SITE)/index.html  (or run: make serve)"

# The teacher's kit (book/teachers.md): a worksheet per question type and the mixed 40-mark
# end-of-topic test, versions A-C with their keys, typeset by xelatex (one run per core),
# and the question bank as Moodle XML. Own sheets: python -m physics_figures.worksheets --help
TEACHERS := $(SITE)/teachers
.PHONY: worksheets moodle
worksheets: venv
	@scripts/ensure-debian-packages pdf
	@echo ">>> typesetting the teachers' worksheets and keys into $(TEACHERS)"
	$(BIN)/python -m physics_figures.worksheets --site --out $(TEACHERS) --work _build/teachers-tex

moodle: venv
	@echo ">>> writing the question bank as Moodle XML"
	$(BIN)/python -m physics_figures.worksheets.moodle $(TEACHERS)/dynamics-moodle.xml

# The tests that need no site start beside the book's build, as two runs at the lowest priority
# (nice 19: the rest of the run waits for the book, then for the site's tests, so those come
# first), each a process of its own: the models, questions and rules (tests/no_site,
# tests/network), and the small books of the build tests (tests/build). They take what the
# book and the site's tests leave of both cores. The two have about as much work (160 and 170
# core-seconds alone), so they get equal shares and end together: a run left alone at the end
# leaves a core idle before Lighthouse (for 8 to 20 s when the small books had more work than
# the other run at the same nice). Two plain runs, not one run on two xdist
# workers: about 25 core-seconds less (no worker collects the other's ten thousand tests, and
# no report crosses a process), and the two still keep both cores busy. Once the book is
# built, the tests of the built site and the browser tests run on both cores (pytest-xdist,
# each test module on one worker; one Chromium a worker), while the first runs finish; then the
# tests that measure speed (marker alone: Lighthouse) run by themselves. The reports follow in
# that order; the runs together are the suite.
# The test folders follow the markers (tests/conftest.py), so each run names its folders and
# collects only their modules.
# The site's run hands its workers the modules in tests/conftest.py's order (RUN_FIRST: the
# longest first), not xdist's own (--no-loadscope-reorder: by number of tests, which put the
# longest last).
NO_SITE_LOG := _build/tests-without-site.log
NO_SITE_TESTS := -p no:cacheprovider tests/no_site tests/network
BUILD_LOG := _build/tests-of-small-books.log
BUILD_TESTS := -p no:cacheprovider tests/build
SITE_TESTS := tests/site tests/browser -m "not alone" -n 2 --dist loadscope --no-loadscope-reorder
# The modules that mark a test `alone`: the run that measures speed collects only them (the
# whole suite's ten thousand tests take seconds to collect while the machine is otherwise idle).
ALONE_FILES = $(shell grep -l "mark\.alone" tests/browser/test_*.py)
# (the venv and the node tools install side by side: both mostly wait for downloads and disk)
test:
	@$(MAKE) --no-print-directory -j2 --output-sync=target venv node_modules/.package-lock.json
	@scripts/ensure-debian-packages test
	@scripts/ensure-debian-packages pdf  # before the tests that need no site: some typeset
	@echo ">>> linting"
	$(BIN)/ruff check $(LINTED)
	@$(MAKE) --no-print-directory jslint
	@mkdir -p _build
	@echo ">>> building the book; beside it, the tests that need no site (reports: $(NO_SITE_LOG), $(BUILD_LOG))"
	@nice -n 19 $(BIN)/python -m pytest $(NO_SITE_TESTS) >$(NO_SITE_LOG) 2>&1 & tests=$$!; \
	  nice -n 19 $(BIN)/python -m pytest $(BUILD_TESTS) >$(BUILD_LOG) 2>&1 & books=$$!; \
	  $(MAKE) --no-print-directory book || { kill $$tests $$books; wait $$tests $$books; exit 1; }; \
	  echo ">>> the tests of the built site, in Chromium too, on both cores"; \
	  $(BIN)/python -m pytest $(SITE_TESTS) && site=0 || site=$$?; \
	  wait $$tests && no_site=0 || no_site=$$?; \
	  wait $$books && built=0 || built=$$?; \
	  echo ">>> the tests that need no site:"; cat $(NO_SITE_LOG); \
	  echo ">>> the tests that build small books of their own:"; cat $(BUILD_LOG); \
	  echo ">>> the tests that measure speed, alone"; \
	  $(BIN)/python -m pytest -m "alone" $(ALONE_FILES) && alone=0 || alone=$$?; \
	  [ $$no_site -eq 0 ] || echo "!!! the tests that need no site failed: see above ($(NO_SITE_LOG))"; \
	  [ $$built -eq 0 ] || echo "!!! the tests that build small books failed: see above ($(BUILD_LOG))"; \
	  [ $$site -eq 0 ] || echo "!!! the tests of the built site failed: see above"; \
	  exit $$(( no_site || built || site || alone ))

# The fast loop: ruff, ESLint, Prettier and every test that needs no build and no browser
# (models, marking rules, questions, notation), with three variants of each template
# (--sample-variants, tests/conftest.py; make test tests every one). Under a minute: pytest
# runs on both cores (pytest-xdist), ESLint and Prettier beside it. A worker takes a whole
# module (--dist loadscope), so a module's fixtures and caches are made once, not on both.
# .pre-commit-config.yaml runs these same commands.
.PHONY: check
check: venv node_modules/.package-lock.json
	$(BIN)/ruff check $(LINTED)
	$(MAKE) --no-print-directory jslint & jslint=$$!; \
	  $(BIN)/python -m pytest tests/no_site -q --sample-variants -n 2 --dist loadscope --no-loadscope-reorder \
	    || { wait $$jslint; exit 1; }; \
	  wait $$jslint

# The site's JavaScript: ESLint (eslint.config.mjs) and Prettier's layout (.prettierrc.json;
# .prettierignore). To reformat: node_modules/.bin/prettier --write "**/*.{js,mjs}"
NODE_BIN := node_modules/.bin
.PHONY: jslint
# Both keep a cache of the files they passed (by content, under node_modules/.cache, which npm ci
# clears): a file unchanged since is not read again, so the fast loop pays only for what changed.
jslint: node_modules/.package-lock.json
	$(NODE_BIN)/eslint --max-warnings=0 --cache --cache-strategy content \
	  --cache-location node_modules/.cache/eslint/ .
	$(NODE_BIN)/prettier --check --log-level=warn --cache --cache-strategy content \
	  --cache-location node_modules/.cache/prettier/cache.json "**/*.{js,mjs}"

# The teachers' PDFs: the book, a question sheet and an answer key. One LaTeX build
# writes all three .tex files (book/_latex/); xelatex typesets them. Needs TeX Live
# from Debian (about 360 MB, no texlive-fonts-extra). The PDFs are copied into the
# site too, so the intro page's download links work.
# The LaTeX build keeps its own Sphinx environment (its doctrees, under $(LATEX_BUILD)):
# sphinx-jupyterbook-latex sets numfig_secnum_depth for LaTeX, and in an environment shared
# with the HTML build that change made the next make html read every page again. It shares
# the HTML build's cache of executed pages (a link), so no page is executed twice.
# make latex writes the .tex files only (tests/build/test_incremental_build.py uses it).
LATEX_BUILD := _build/latex-build
PDF := $(LATEX_BUILD)/_build/latex
PDF_FILES := dynamics.pdf dynamics-questions.pdf dynamics-answers.pdf
LATEX_ENV := mkdir -p _build/.jupyter_cache $(LATEX_BUILD)/_build && \
  ln -sfn ../../.jupyter_cache $(LATEX_BUILD)/_build/.jupyter_cache

.PHONY: pdf latex
latex: venv
	@$(LATEX_ENV)
	$(JB_BUILD) --builder latex --path-output $(LATEX_BUILD)

pdf: venv
	@scripts/ensure-debian-packages pdf
	@echo ">>> building the PDFs with xelatex (pages are executed; cached pages are reused)"
	@$(LATEX_ENV)
	$(JB_BUILD) --builder pdflatex --path-output $(LATEX_BUILD)
	@mkdir -p $(SITE)/pdf
	cp $(addprefix $(PDF)/,$(PDF_FILES)) $(SITE)/pdf/
	@echo ">>> done: $(addprefix $(PDF)/,$(PDF_FILES)) (copied to $(SITE)/pdf/)"

serve:
	@test -f $(SITE)/index.html || { echo "!!! no site yet: run 'make book' first"; exit 1; }
	@echo ">>> serving $(SITE) on http://localhost:$(PORT) (Ctrl-C to stop)"
	$(PYTHON) -m http.server $(PORT) --bind 127.0.0.1 --directory $(SITE)

LINTED := physics_figures tests book/_ext book/_latex scripts
lint: venv jslint
	$(BIN)/ruff check $(LINTED)

clean:
	rm -rf _build .pytest_cache .hypothesis

# Build times (cold, no-op, one page edited, one figure function edited) on a copy of the
# repository, every page's gzip bytes against a default Jupyter Book page, Lighthouse on
# every page: written to BENCHMARKS.md. Needs chromium and node (npm ci for the tools).
.PHONY: bench
bench: venv node_modules/.package-lock.json
	$(BIN)/python scripts/bench.py
