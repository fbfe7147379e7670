# Thin wrapper over CMake: the README's two commands, `make demo` and `make test`.
BUILD ?= build
CMAKE_FLAGS ?=
# where `make install` puts footsim (bin/, lib/, include/, share/footsim/, share/man/)
PREFIX ?= /usr/local
# extra ctest arguments, e.g. CTEST_ARGS='-L fast'
CTEST_ARGS ?=
JOBS ?= $(shell nproc 2>/dev/null || echo 2)

.PHONY: all deps configure build demo test check asan install clean

all: build

deps:
	@sh tools/install-deps.sh

$(BUILD)/CMakeCache.txt:
	@sh tools/install-deps.sh
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

configure: $(BUILD)/CMakeCache.txt

build: configure
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	$(BUILD)/footsim demo

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) $(CTEST_ARGS)

# Only the tests labelled fast (under a minute in all): for the edit-build-check loop.
check: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) -L fast $(CTEST_ARGS)

# The whole suite under AddressSanitizer and UndefinedBehaviorSanitizer, in its own build folder.
asan:
	$(MAKE) test BUILD=build-asan CMAKE_FLAGS="-DCMAKE_BUILD_TYPE=Debug -DFS_SANITIZE=ON $(CMAKE_FLAGS)"

# The command, libfootsim (+ footsim.pc), its headers, the shipped scenarios and terrains, the man page.
install: build
	cmake --install $(BUILD) --prefix $(PREFIX)

clean:
	rm -rf $(BUILD) build-asan build-norender
