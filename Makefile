# pumpd: the two commands of the README.
#   make run  [SCENE=prm/<file>.prm]   install what is missing, configure, build, run the main job
#   make test                          install what is missing, configure, build, ctest (no bench/study)
# Also: make bench, make study (the long labels), make clean.
BUILD ?= build
SCENE ?= prm/ingraffea-case2.prm
JOBS  ?= 2

.PHONY: run test bench study deps configure build clean

deps:
	@scripts/install-deps.sh

configure: deps
	@test -f $(BUILD)/CMakeCache.txt || cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j$(JOBS)

run: build
	$(BUILD)/coupling/pumpd $(SCENE)
	@dir=$$(sed -n 's/^ *set Output directory *= *//p' $(SCENE)); \
	  if [ -f "$$dir/damage.csv" ]; then /usr/bin/python3 scripts/plot_pd_damage.py "$$dir"; fi; \
	  if [ -f "$$dir/crack_path.csv" ]; then /usr/bin/python3 scripts/plot_crack_path.py "$$dir"; fi; \
	  if [ -f "$$dir/load_displacement.csv" ]; then /usr/bin/python3 scripts/plot_load_displacement.py "$$dir" $(SCENE); fi

test: build
	cd $(BUILD) && ctest -LE "bench|study" --output-on-failure

bench: build
	cd $(BUILD) && ctest -L bench --output-on-failure

study: build
	cd $(BUILD) && ctest -L study --output-on-failure

clean:
	rm -rf $(BUILD)
