# Two commands on a fresh machine: `make demo` and `make test`. Both create .venv when it is missing.
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed
DEMO_OUT ?= demo-out

DEMO_SERVE ?= 1

.PHONY: demo test numeric-kernels lint system-deps clean chromium frontend

# System libraries some back-ends need (Open3D's shared library loads libusb); installed when root.
system-deps:
	@if [ "$$(id -u)" = "0" ] && command -v apt-get >/dev/null; then \
		if ! dpkg -s libusb-1.0-0 >/dev/null 2>&1; then \
			apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libusb-1.0-0 >/dev/null; \
		fi; \
	else echo "system-deps: not root or no apt-get; make sure libusb-1.0-0 is installed"; fi

# Debian's chromium for the review app's end-to-end tests (Playwright drives it by executable_path:
# Playwright's own browser download is not used). Installed when root and missing.
chromium:
	@if [ ! -x /usr/bin/chromium ]; then \
		if [ "$$(id -u)" = "0" ] && command -v apt-get >/dev/null; then \
			apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null; \
		else echo "chromium: not root or no apt-get; the end-to-end tests will be skipped"; fi; \
	fi

# The review app's front end (sigma.js, graphology, three.js) bundled by esbuild into src/coindie/serve/static
# (committed: running coindie serve needs no node).
frontend:
	cd frontend && npm ci --no-audit --no-fund && npm run build

$(STAMP): pyproject.toml requirements-dev.txt
	$(MAKE) --no-print-directory system-deps
	$(MAKE) --no-print-directory chromium
	test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q -r requirements-dev.txt -e .
	touch $(STAMP)

demo: $(STAMP)
	$(VENV)/bin/coindie demo $(DEMO_OUT)
	@if [ "$(DEMO_SERVE)" != "0" ]; then \
		echo "Review the clusters in the browser (Ctrl-C stops; DEMO_SERVE=0 skips this):"; \
		$(VENV)/bin/coindie serve $(DEMO_OUT)/project; \
	fi

# The numerically sensitive tests (marked numeric) again under two other OpenBLAS kernels, so that the suite
# does not hold only for this CPU's (numpy's and scipy's OpenBLAS are DYNAMIC_ARCH builds: OPENBLAS_CORETYPE
# picks the kernel; threadpoolctl.threadpool_info() reports it; Zen runs the Haswell kernels). A kernel the
# CPU cannot run (Sandybridge needs AVX, Zen AVX2, SkylakeX AVX-512) is skipped. About 10-20 s a kernel.
NUMERIC_KERNELS ?= Sandybridge:avx Zen:avx2 SkylakeX:avx512f
NUMERIC_TESTS = $(shell grep -l "pytest.mark.numeric" tests/test_*.py)

test: $(STAMP) chromium
	$(VENV)/bin/ruff check src tests benchmarks
	$(PY) -m pytest -n 2 -q
	$(MAKE) --no-print-directory numeric-kernels

numeric-kernels: $(STAMP)
	@for pair in $(NUMERIC_KERNELS); do \
		kernel=$${pair%%:*}; flag=$${pair##*:}; \
		if grep -qw "$$flag" /proc/cpuinfo 2>/dev/null; then \
			echo "numeric tests under OPENBLAS_CORETYPE=$$kernel"; \
			OPENBLAS_CORETYPE=$$kernel $(PY) -m pytest -q -m numeric -p no:cacheprovider $(NUMERIC_TESTS) || exit 1; \
		else echo "numeric tests: OPENBLAS_CORETYPE=$$kernel skipped (this CPU has no $$flag)"; fi; \
	done

lint: $(STAMP)
	$(VENV)/bin/ruff check src tests benchmarks
	$(VENV)/bin/ruff format --check src tests benchmarks

clean:
	rm -rf $(VENV) $(DEMO_OUT) .pytest_cache
