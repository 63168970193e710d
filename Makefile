# The two commands README gives, plus the pieces they are made of. All targets are idempotent.
.PHONY: demo test build core ros bench fuzz deps format clean

demo: deps build          ## install what is missing, build, run the demo
	scripts/demo.sh

test:                     ## install what is missing, build, run every test; ends "N passed, N failed"
	scripts/run_tests.sh

deps:
	scripts/install_deps.sh

build: deps
	scripts/build.sh all

core:
	scripts/build.sh core

ros:
	scripts/build.sh ros

bench: deps
	scripts/bench.sh

fuzz: deps
	scripts/fuzz.sh --seconds 60

format:
	find include src tools test bench fuzz -name '*.cpp' -o -name '*.h' | xargs clang-format -i

clean:
	rm -rf build devel
