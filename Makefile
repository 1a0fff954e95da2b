# The two commands of the README do all set-up: `make demo` and `make test`.
# Both are idempotent: the venv is rebuilt only when pyproject.toml changes.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
# Debian packages manim needs to build pycairo/manimpango, the font the theme uses,
# xdg-open (manim's preview crashes after rendering without it), and chromium (the tests of
# `trex player` and `trex slides` drive their pages in it headless, through playwright, which
# plays the slides' H.264 clips; no browser is ever downloaded). The handout's font is DejaVu.
DEB_PACKAGES := libpango1.0-dev pkg-config fonts-dejavu-core xdg-utils chromium

.PHONY: demo test test-fast lint system-deps bench clean

demo: $(STAMP)
	$(BIN)/manim -ql --disable_caching scenes/gravity.py Gravity
	@echo "video: $(CURDIR)/media/videos/gravity/480p15/Gravity.mp4"

test: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/lint-imports
	$(BIN)/mypy
	$(BIN)/python -m pytest -n 2

# The edit-test loop: the tracing, geometry, usercode and story tests only (tests/conftest.py's
# --fast picks them by what they import), without the hypothesis sweeps, under a minute;
# `make test` stays the whole suite.
test-fast: $(STAMP)
	$(BIN)/python -m pytest -n 2 -q --fast

lint: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/lint-imports
	$(BIN)/mypy

bench: $(STAMP)
	$(BIN)/python -m bench.trace_overhead
	$(BIN)/python -m bench.algorithms
	$(BIN)/python -m bench.holes
	$(BIN)/python -m bench.render
	$(BIN)/python -m bench.lecture
	$(BIN)/python -m bench.slides
	$(BIN)/python -m bench.studio
	$(BIN)/python -m bench.course

$(STAMP): pyproject.toml | system-deps
	test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e ".[test,bench]"
	touch $(STAMP)

system-deps:
	@missing=""; \
	pkg-config --exists pangocairo 2>/dev/null || missing="$$missing libpango1.0-dev pkg-config"; \
	test -e /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf || missing="$$missing fonts-dejavu-core"; \
	command -v xdg-open >/dev/null || missing="$$missing xdg-utils"; \
	test -x /usr/bin/chromium || missing="$$missing chromium"; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	    echo "installing Debian packages:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $(DEB_PACKAGES); \
	  else \
	    echo "missing system packages; run:  sudo apt-get install -y --no-install-recommends $(DEB_PACKAGES)"; \
	    exit 1; \
	  fi; \
	fi

clean:
	rm -rf $(VENV) media/videos media/images media/texts media/Tex
