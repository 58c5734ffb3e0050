# flipflop — the two commands of the README.
#   make demo   set up, build (Release, build/), run the demo job
#   make test   set up, build, run the whole test suite through ctest
BUILD ?= build
JOBS  ?= $(shell nproc)
PKGS  := cmake g++ make libgmp-dev libmpfr-dev libcgal-dev libeigen3-dev libtbb-dev \
         libqhull-dev qhull-bin catch2 librapidcheck-dev libcli11-dev

.PHONY: all deps configure build demo test clean

all: build

deps:
	@missing=""; for p in $(PKGS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  echo "flipflop: installing missing Debian packages:$$missing"; \
	  if [ "$$(id -u)" -ne 0 ]; then SUDO=sudo; else SUDO=; fi; \
	  $$SUDO apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq --no-install-recommends $$missing; \
	fi

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release > $(BUILD).configure.log 2>&1 || \
	  { cat $(BUILD).configure.log; exit 1; }

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/flipflop demo

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD) $(BUILD).configure.log
