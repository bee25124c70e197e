# IncirCu developer commands. `make demo` and `make test` do everything on a fresh Debian/Ubuntu machine.
SHELL := /bin/bash
.DEFAULT_GOAL := help

PLUGIN := incircu
VERSION := $(shell sed -n 's/^version=//p' metadata.txt)
VENV := .venv
PYTHON := $(VENV)/bin/python
SYSTEM_PYTHON := /usr/bin/python3
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
DEBIAN_PACKAGES := qgis python3-qgis qgis-providers python3-numpy python3-pyproj python3-venv python3-pip python3-dev \
	libgeos-dev proj-bin build-essential pkg-config pyqt5-dev-tools qttools5-dev-tools git make
# proj-bin: the distribution's pyproj finds PROJ's data next to the `proj` program when it runs in the venv.
# The distribution's Shapely, installed with the packages above where it is Shapely 2 (Debian 13, Ubuntu 24.04).
SHAPELY_PACKAGE = $$(apt-cache policy python3-shapely | sed -n 's/^ *Candidate: *[2-9]\..*/python3-shapely/p')
# Python packages for QGIS's own Python (qgis_process, QGIS desktop): Shapely on the system GEOS, since the wheel's
# bundled GEOS clashes with the one QGIS links. The distribution's Shapely 2 when there is one, else built here
# from the pin; numpy and pyproj come from the distribution.
QGIS_SITE := $(VENV)/qgis-site
SHAPELY_PIN := $(shell sed -n 's/^\(shapely==[^ ;]*\).*/\1/p' requirements.txt)
# Whether QGIS's Python has Shapely 2, judged by its API as the plugin judges it (algorithms/dependencies.py), not by
# its version: Debian's python3-shapely 2.2 reports "0+unknown".
SYSTEM_HAS_SHAPELY2 := import sys; sys.path.append("algorithms"); import shapely, dependencies; \
	sys.exit(bool(dependencies.missing_shapely2_api(shapely)))
PROFILE ?= default
QGIS_PROFILE_DIR ?= $(HOME)/.local/share/QGIS/QGIS3/profiles/$(PROFILE)
DIST := dist
# What a user installs: everything else (tests, benchmarks, scripts, CI, docs) stays out of the release zip; the
# packaged README links what it references outside the zip on the repository (scripts/release_links.py).
RELEASE_PATHS := metadata.txt LICENSE __init__.py README.md incircu_plugin algorithms icons i18n help models styles
export QT_QPA_PLATFORM := offscreen
# Keep the tests' and the demo's QGIS settings out of the user's profile.
export QGIS_CUSTOM_CONFIG_PATH ?= $(CURDIR)/out/qgis-profile
export PYTHONDONTWRITEBYTECODE := 1

.PHONY: help help-page setup system-packages demo label-style test test-core lint package deploy transup transcompile bench fuzz clean

help:
	@echo "make setup        install QGIS (Debian packages, if absent) and the pinned Python tools into $(VENV)"
	@echo "make demo         run IncirCu with qgis_process on the sample data; writes out/demo.gpkg and out/demo.png"
	@echo "make test         run every test and doctest on a real, offscreen QGIS"
	@echo "make test-core    the geometry core's tests and doctests, no QGIS needed, slow tests left out (< 1 min)"
	@echo "make lint         ruff"
	@echo "make package      release zip in $(DIST)/ (git archive of HEAD)"
	@echo "make deploy       copy the plugin into the QGIS profile $(PROFILE)"
	@echo "make transup      update i18n/*.ts from the sources; make transcompile builds the .qm files"
	@echo "make help-page    write the offline help page help/index.html from the algorithms (after a help text changed)"
	@echo "make bench        benchmarks (bash benchmarks/run.sh)"
	@echo "make fuzz N=100000  fuzz campaign of the core (fuzz/), alone and in batches, prints the outcome table"

setup: system-packages $(VENV)/.installed $(QGIS_SITE)/.installed

system-packages:
	@if ! $(SYSTEM_PYTHON) -c "import qgis.core, pyproj, numpy, venv, ensurepip" 2>/dev/null \
	    || ! command -v qgis_process.bin >/dev/null 2>&1 || ! command -v lrelease >/dev/null 2>&1 \
	    || ! command -v geos-config >/dev/null 2>&1 || ! command -v gcc >/dev/null 2>&1 \
	    || ! command -v proj >/dev/null 2>&1; then \
	  echo "Installing QGIS and tools from the distribution's packages"; \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -q && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends $(DEBIAN_PACKAGES) \
	    $(SHAPELY_PACKAGE); \
	fi

$(VENV)/.installed: requirements.txt requirements-dev.txt
	@[ -x $(PYTHON) ] || $(SYSTEM_PYTHON) -m venv --system-site-packages $(VENV)
	$(PYTHON) -m pip install --quiet --disable-pip-version-check -r requirements-dev.txt
	@touch $@

# Where Shapely is built (no distribution Shapely 2: Debian 12, Ubuntu 22.04), it is built without build isolation,
# with the pinned tools of requirements-build.txt against the venv's numpy (requirements.txt's 1.26 pin before Python
# 3.13, the distribution's from 3.13): an isolated build takes the newest Cython and numpy, a pair that has broken
# it. Built on numpy 1.26's headers, Shapely runs on Debian 12's numpy 1.24 too (numpy builds for 1.19 and later).
$(QGIS_SITE)/.installed: requirements.txt requirements-build.txt $(VENV)/.installed
	@mkdir -p $(QGIS_SITE)
	@if $(SYSTEM_PYTHON) -c '$(SYSTEM_HAS_SHAPELY2)' 2>/dev/null; then \
	  echo "QGIS's Python uses the distribution's Shapely 2: nothing to build"; \
	else \
	  $(PYTHON) -m pip install --quiet --disable-pip-version-check -r requirements-build.txt && \
	  PATH="$(CURDIR)/$(VENV)/bin:$$PATH" $(PYTHON) -m pip install --quiet --disable-pip-version-check --no-deps \
	    --no-binary shapely --no-build-isolation --upgrade --target $(QGIS_SITE) "$(SHAPELY_PIN)"; \
	fi
	@touch $@

demo: setup
	$(PYTHON) scripts/demo.py

# The example lake-label style (styles/lake_labels.qml) and its README picture, rendered by QGIS.
label-style: setup
	$(PYTHON) scripts/make_label_style.py

# pytest-qgis starts QGIS with its GUI classes (the dialog tests need them) on the offscreen platform exported above.
CORE_DOCTESTS := --doctest-modules incircu_plugin/core
# The core relies on GEOS keeping z through its Delaunay triangulation (of one line of samples per polygon), and
# bad input must get its typed error without GEOS warnings: these tests run again on the Shapely built for QGIS's
# own Python on the system GEOS where make setup built one (where QGIS uses the distribution's Shapely, nothing is
# built and this pass is skipped).
GEOS_TESTS := tests/test_core_warnings.py tests/test_core_contacts.py tests/test_core_skeleton.py tests/test_core_polyline.py tests/test_core_errors.py
test: setup
	$(PYTHON) -m pytest -p no:cacheprovider -o qgis_gui_enabled=true tests $(CORE_DOCTESTS)
	@if [ -d $(QGIS_SITE)/shapely ]; then \
	  echo "== again on QGIS's Shapely (system GEOS)"; \
	  PYTHONPATH=$(QGIS_SITE) $(PYTHON) -m pytest -p no:cacheprovider -p no:pytest_qgis -q -m "not slow" -W error::RuntimeWarning $(GEOS_TESTS); \
	else \
	  echo "== no Shapely was built for QGIS's Python (it uses the distribution's): no second pass"; \
	fi

# The fast path: numpy, shapely, pyproj and the test tools only; pytest-qgis is switched off, so no QGIS starts
# (nor needs to be installed). Tests marked slow (pytest.ini) run in `make test` only.
test-core: $(VENV)/.installed
	$(PYTHON) -m pytest -p no:cacheprovider -p no:pytest_qgis -m "not slow" tests/test_core_*.py tests/test_docs.py $(CORE_DOCTESTS)

lint: setup
	$(PYTHON) -m ruff check .
	$(PYTHON) -m ruff format --check .

package:
	@mkdir -p $(DIST)
	git archive --format=zip --prefix=$(PLUGIN)/ -o $(DIST)/$(PLUGIN)-$(VERSION).zip HEAD $(RELEASE_PATHS)
	$(SYSTEM_PYTHON) scripts/release_links.py $(DIST)/$(PLUGIN)-$(VERSION).zip
	@echo "$(DIST)/$(PLUGIN)-$(VERSION).zip"

deploy: package
	@mkdir -p $(QGIS_PROFILE_DIR)/python/plugins
	rm -rf $(QGIS_PROFILE_DIR)/python/plugins/$(PLUGIN)
	cd $(QGIS_PROFILE_DIR)/python/plugins && $(SYSTEM_PYTHON) -m zipfile -e $(CURDIR)/$(DIST)/$(PLUGIN)-$(VERSION).zip .
	@echo "Deployed to $(QGIS_PROFILE_DIR)/python/plugins/$(PLUGIN); enable IncirCu in the Plugin Manager."

transup:
	pylupdate5 -noobsolete incircu_plugin/plugin.py incircu_plugin/provider.py incircu_plugin/core/errors.py algorithms/*.py -ts i18n/incircu_pl.ts

transcompile:
	lrelease i18n/*.ts

help-page:
	PYTHONPATH=$(QGIS_SITE) $(SYSTEM_PYTHON) scripts/make_help.py

bench: setup
	bash benchmarks/run.sh

N ?= 100000
SEED ?= 20261201
TOGETHER ?= 16
fuzz: $(VENV)/.installed
	$(PYTHON) -m fuzz --count $(N) --seed $(SEED) --together $(TOGETHER) --failures out/fuzz/failures-$(SEED).jsonl

clean:
	rm -rf $(DIST) out tests/artifacts
