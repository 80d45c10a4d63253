# rayo - build, test, install.
#
#   make                 build/rayo, build/librayo.a and build/librayo.so.*
#   make V=1             the same, printing every command in full
#   make check           every test, run by prove (TAP), CHECK_JOBS at once
#   make run             render the assignment's sphere to esfera.pbm and esfera.png
#   make bench           benchmarks (bench/; BENCH_ARGS="--only peers")
#   make check-sanitize  every test under ASan and UBSan (clang)
#   make check-valgrind  the command tests under valgrind memcheck
#   make fuzz            libFuzzer targets (fuzz/; docs/robustness.md)
#   make install PREFIX=/usr/local
#   make pot             po/rayo.pot from the marked messages (docs/i18n.md)
#   make update-po       po/*.po merged with po/rayo.pot (msgmerge)
#   make CC=clang        any C11 compiler; warnings are errors
#   make BUILD=dir       build somewhere else (parallel work trees, sanitizers)
#
# Sources are found by wildcard: a new file under src/ joins the library,
# cli/ the command, tests/unit/t_*.c a unit test, tests/cli/*.t a command test.

CC ?= cc
# Tests get the compiler that built rayo as RAYO_CC (with LDFLAGS, so a
# student's program links to a sanitized librayo.a); CC itself stays out
# of their environment, where it would change the compiler `rayo grade`
# gives students (make check CC=clang, make check-sanitize).
unexport CC
BUILD ?= build
PREFIX ?= /usr/local
PKG_CONFIG ?= pkg-config
AR ?= ar

# Evaluated when used, so they see a libpng that scripts/deps.sh has just
# installed on a fresh machine.
PNG_CFLAGS = $(shell $(PKG_CONFIG) --cflags libpng 2>/dev/null)
PNG_LIBS = $(shell $(PKG_CONFIG) --libs libpng 2>/dev/null || echo -lpng)
JPEG_CFLAGS = $(shell $(PKG_CONFIG) --cflags libjpeg 2>/dev/null)
JPEG_LIBS = $(shell $(PKG_CONFIG) --libs libjpeg 2>/dev/null || echo -ljpeg)

OPT ?= -O2 -g
WARNINGS := -Wall -Wextra -Werror -pedantic -Wshadow -Wstrict-prototypes \
            -Wmissing-prototypes -Wformat=2
CFLAGS ?=
ALL_CFLAGS = -std=c11 $(OPT) $(WARNINGS) -Iinclude $(PNG_CFLAGS) \
              $(JPEG_CFLAGS) $(CFLAGS) \
              -MMD -MP
# zlib (which libpng-dev brings): the command reads students' zip files
# (cli/zip_read.c).
LDLIBS = $(PNG_LIBS) $(JPEG_LIBS) -lz -lpthread -lm

# Builds speak softly: one line per file made ("  CC  src/x.c"); V=1
# prints the commands themselves, make -s nothing.
V ?= 0
ifeq ($(V),1)
Q :=
say = @:
else
Q := @
say = @printf '  %-4s%s\n' '$(1)' '$(2)'
endif
ifneq ($(findstring s,$(firstword -$(filter-out --%,$(MAKEFLAGS)))),)
say = @:
endif

# The library: every public function is marked RAYO_API
# (include/rayo/export.h) and everything else is compiled hidden, so the
# shared library exports exactly the headers' functions
# (tests/cli/exports.t).  The same position-independent objects make
# librayo.a and librayo.so.$(RAYO_VERSION), whose soname carries
# SO_MAJOR: raise it when a release changes or removes a public function
# or type (adding one does not).
RAYO_VERSION := $(shell sed -n 's/^\#define RAYO_VERSION "\(.*\)"/\1/p' include/rayo.h)
SO_MAJOR := 0
SO_NAME := librayo.so.$(SO_MAJOR)
LIB_CFLAGS := -fPIC -fvisibility=hidden

# The functions harnesses (src/grade/functions/harness/) are programs of
# their own, built into the library as text, not compiled into it.
HARNESS_DIR := src/grade/functions/harness
LIB_SRC := $(sort $(filter-out $(HARNESS_DIR)/%,$(shell find src -name '*.c')))
CLI_SRC := $(sort $(wildcard cli/*.c))
UNIT_SRC := $(sort $(wildcard tests/unit/t_*.c))
UNIT_SUPPORT := $(filter-out $(UNIT_SRC),$(wildcard tests/unit/*.c))
BENCH_SRC := $(sort $(wildcard bench/*.c))

LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o) $(BUILD)/obj/gen/course_png.o \
           $(BUILD)/obj/gen/harness_src.o
CLI_OBJ := $(CLI_SRC:%.c=$(BUILD)/obj/%.o)
UNIT_BIN := $(UNIT_SRC:tests/unit/%.c=$(BUILD)/tests/%)
UNIT_SUPPORT_OBJ := $(UNIT_SUPPORT:%.c=$(BUILD)/obj/%.o)

# The translations (po/LL.po, docs/i18n.md): compiled by msgfmt into
# $(BUILD)/locale/LL/LC_MESSAGES/rayo.mo, and embedded in the library as
# $(BUILD)/gen/catalogs.c, so that a copied binary and the page need no
# file to speak them.
PO_LANGS := $(patsubst po/%.po,%,$(sort $(wildcard po/*.po)))
MO_FILES := $(PO_LANGS:%=$(BUILD)/locale/%/LC_MESSAGES/rayo.mo)
CATALOG_SRC := $(BUILD)/gen/catalogs.c
CATALOG_OBJ := $(BUILD)/obj/gen/catalogs.o
LIB_OBJ += $(CATALOG_OBJ)

LIB := $(BUILD)/librayo.a
SHLIB := $(BUILD)/librayo.so.$(RAYO_VERSION)
RAYO := $(BUILD)/rayo

.PHONY: all check run install uninstall clean bench setup-steps check-sanitize \
        check-valgrind unit cli-tests fuzz fuzz-targets
.DEFAULT_GOAL := all

all: $(RAYO) $(LIB) $(SHLIB)

# What a fresh Debian machine lacks is installed once (scripts/deps.sh).
$(BUILD)/.deps-build:
	@scripts/deps.sh build
	@mkdir -p $(dir $@) && touch $@
$(BUILD)/.deps-check:
	@scripts/deps.sh check
	@mkdir -p $(dir $@) && touch $@
$(BUILD)/.deps-bench:
	@scripts/deps.sh bench
	@mkdir -p $(dir $@) && touch $@
$(BUILD)/.deps-web:
	@scripts/deps.sh web
	@mkdir -p $(dir $@) && touch $@

$(BUILD)/obj/%.o: %.c | $(BUILD)/.deps-build
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) $(ALL_CFLAGS) -c $< -o $@

$(LIB_OBJ): ALL_CFLAGS += $(LIB_CFLAGS)

# The course's reference images (data/course/*.png) built into the
# library as arrays (rayo_course_reference_png), so a copied or installed
# command needs no data files for course:ej1 and --reference course.
COURSE_PNG := $(sort $(wildcard data/course/*.png))
$(BUILD)/gen/course_png.c: scripts/embed.sh $(COURSE_PNG)
	@mkdir -p $(dir $@)
	$(call say,GEN,$@)
	$(Q)scripts/embed.sh $(foreach f,$(COURSE_PNG),$(patsubst \
	    referencia-catedra-%.png,course_png_%,$(notdir $(f)))=$(f)) >$@.tmp
	$(Q)mv $@.tmp $@

$(BUILD)/obj/gen/course_png.o: $(BUILD)/gen/course_png.c | $(BUILD)/.deps-build
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) $(ALL_CFLAGS) -Isrc/course -c $< -o $@

# The functions harnesses as bytes (harness_sources.h), which the
# grader writes beside a student's objects; `make check` also compiles
# each on its own with the course's flags and links it, as the grader
# does, with a right student program of tests/grade/, so that a typo in
# a harness fails the checks, not a grade (t_grade_functions runs them).
HARNESS_FILES := $(HARNESS_DIR)/rayo_harness.h \
                 $(sort $(wildcard $(HARNESS_DIR)/*.c))
$(BUILD)/gen/harness_src.c: scripts/embed.sh $(HARNESS_FILES)
	@mkdir -p $(dir $@)
	$(call say,GEN,$@)
	$(Q)scripts/embed.sh --header harness_sources.h $(foreach f,$(HARNESS_FILES),\
	    harness_$(subst .,_,$(notdir $(f)))=$(f)) >$@.tmp
	$(Q)mv $@.tmp $@

$(BUILD)/obj/gen/harness_src.o: $(BUILD)/gen/harness_src.c | $(BUILD)/.deps-build
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) $(ALL_CFLAGS) -Isrc/grade/functions -c $< -o $@

HARNESS_BIN := $(patsubst $(HARNESS_DIR)/%.c,$(BUILD)/harness/%,$(sort $(wildcard $(HARNESS_DIR)/*.c)))
HARNESS_STUDENT_ej1 := tests/grade/correct/main.c
HARNESS_STUDENT_ej2 := tests/grade/ej2_correct/main.c
HARNESS_STUDENT_ej3 := tests/grade/ej3_correct/main.c
HARNESS_LINK_ej3 := $(shell sed -n 's/"\([^"]*\)",\{0,1\}/\1/gp' src/grade/functions/ej3_link.def)
check check-valgrind: $(HARNESS_BIN)
$(BUILD)/harness/ej1: $(HARNESS_STUDENT_ej1)
$(BUILD)/harness/ej2: $(HARNESS_STUDENT_ej2)
$(BUILD)/harness/ej3: $(HARNESS_STUDENT_ej3)

$(BUILD)/harness/%: $(HARNESS_DIR)/%.c $(HARNESS_DIR)/rayo_harness.h
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) -std=c99 -Wall -Werror -pedantic $(OPT) $(CFLAGS) -c -o $@.o $<
	$(Q)$(CC) -std=c99 -w -Dmain=rayo_student_main $(OPT) $(CFLAGS) -c \
	    -o $@.student.o $(HARNESS_STUDENT_$*)
	$(Q)$(CC) $(LDFLAGS) -o $@ $@.o $@.student.o $(HARNESS_LINK_$*) -lm

$(BUILD)/locale/%/LC_MESSAGES/rayo.mo: po/%.po | $(BUILD)/.deps-build
	@mkdir -p $(dir $@)
	$(call say,MO,$@)
	$(Q)msgfmt --check -o $@ $<

$(CATALOG_SRC): $(MO_FILES) scripts/embed_catalogs.sh
	@mkdir -p $(dir $@)
	$(call say,GEN,$@)
	$(Q)scripts/embed_catalogs.sh $@ $(BUILD)/locale $(PO_LANGS)

$(CATALOG_OBJ): $(CATALOG_SRC) src/core/catalog.h
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) $(ALL_CFLAGS) -Isrc/core -c $< -o $@

.PHONY: pot update-po
pot:
	scripts/update_pot.sh po/rayo.pot

update-po: pot
	for po in po/*.po; do \
	    msgmerge --quiet --update --backup=none --no-wrap \
	        --add-location=file $$po po/rayo.pot \
	        || exit 1; done

$(LIB): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	$(call say,AR,$@)
	$(Q)rm -f $@
	$(Q)$(AR) rcs $@ $^

$(SHLIB): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) -shared -Wl,-soname,$(SO_NAME) $(LDFLAGS) -o $@ $^ $(LDLIBS)
	$(Q)ln -sf $(notdir $@) $(BUILD)/$(SO_NAME)
	$(Q)ln -sf $(SO_NAME) $(BUILD)/librayo.so

$(RAYO): $(CLI_OBJ) $(LIB)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $(CLI_OBJ) $(LIB) $(LDLIBS)

$(BUILD)/tests/%: tests/unit/%.c $(UNIT_SUPPORT_OBJ) $(LIB)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -Itests/unit $(LDFLAGS) -o $@ $< \
	    $(UNIT_SUPPORT_OBJ) $(LIB) $(LDLIBS)

unit: $(UNIT_BIN)

# Every test, as TAP, through prove.  Command tests find the build through
# the environment, so `make check BUILD=build-asan` tests that build.
# CHECK_JOBS files run at once (the CPUs; CHECK_JOBS=1 one at a time);
# those in CHECK_ALONE, which measure time, send signals or limit memory,
# are given no prove rule, and prove runs such files one by one after
# the others, each alone.  The last line says how it went and how long.
CHECK_JOBS ?= $(shell getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
CHECK_ALONE := tests/cli/progress.t tests/cli/signals.t \
               tests/cli/grade_sandbox.t tests/cli/limits.t \
               tests/cli/grade_limits.t
CHECK_FILES = $(UNIT_BIN) $(sort $(wildcard tests/cli/*.t))
CHECK_RULES = $(foreach f,$(filter-out $(CHECK_ALONE),$(CHECK_FILES)), \
                  --rules='par=$(f)')
check: all $(UNIT_BIN) | $(BUILD)/.deps-check
	@echo "check: $(words $(CHECK_FILES)) test files, $(CHECK_JOBS) at a" \
	    "time, then $(words $(CHECK_ALONE)) alone (a few minutes)"
	$(Q)start=$$(date +%s); \
	RAYO=$(abspath $(RAYO)) RAYO_BUILD=$(abspath $(BUILD)) \
	RAYO_CC="$(CC) $(LDFLAGS)" RAYO_SOURCE=$(CURDIR) \
	    prove -f --exec '' -j $(CHECK_JOBS) $(CHECK_RULES) \
	    $(CHECK_FILES); status=$$?; s=$$(( $$(date +%s) - start )); \
	if [ $$status -eq 0 ]; then r=passed; else r=FAILED; fi; \
	printf 'check: %s, %d test files in %d min %02d s\n' "$$r" \
	    $(words $(CHECK_FILES)) $$((s / 60)) $$((s % 60)); \
	exit $$status

run: $(RAYO)
	$(call say,RUN,$(RAYO) -o esfera.pbm)
	$(Q)$(RAYO) -o esfera.pbm
	$(call say,RUN,$(RAYO) -o esfera.png)
	$(Q)$(RAYO) -o esfera.png
	@echo "wrote esfera.pbm and esfera.png"

# The whole suite with AddressSanitizer and UndefinedBehaviorSanitizer.
check-sanitize:
	$(MAKE) check CC=clang BUILD=$(BUILD)-sanitize RAYO_SKIP_WEB=1 \
	    OPT="-O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" \
	    LDFLAGS="-fsanitize=address,undefined"

# Fuzzing (fuzz/, docs/robustness.md): each fuzz/fuzz_NAME.c is a target.
# `make fuzz` links them with libFuzzer, ASan and UBSan (clang) as
# $(BUILD)-fuzz/fuzz/fuzz-NAME (fuzz/run.sh runs them); `make check`
# links them with fuzz/replay.c as $(BUILD)/fuzz/replay-NAME and replays
# fuzz/corpus/NAME and fuzz/regression/NAME.  They reach the library
# through its public headers and the command through its own (-Icli:
# cli_parse.h, zip_read.h), linked with the command's objects but main.o.
FUZZ_NAMES := $(patsubst fuzz/fuzz_%.c,%,$(sort $(wildcard fuzz/fuzz_*.c)))
FUZZ_SUPPORT_OBJ := $(patsubst %.c,$(BUILD)/obj/%.o,$(filter-out \
    fuzz/fuzz_%.c fuzz/replay.c,$(sort $(wildcard fuzz/*.c)))) \
    $(filter-out $(BUILD)/obj/cli/main.o,$(CLI_OBJ))
FUZZ_REPLAY := $(FUZZ_NAMES:%=$(BUILD)/fuzz/replay-%)
.SECONDARY: $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard fuzz/*.c))
$(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard fuzz/*.c)): ALL_CFLAGS += -Icli
# Defined after the check rules read their prerequisites, so named here.
check check-valgrind: $(FUZZ_REPLAY)

$(BUILD)/fuzz/replay-%: $(BUILD)/obj/fuzz/fuzz_%.o $(BUILD)/obj/fuzz/replay.o \
    $(FUZZ_SUPPORT_OBJ) $(LIB)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/fuzz/fuzz-%: $(BUILD)/obj/fuzz/fuzz_%.o $(FUZZ_SUPPORT_OBJ) $(LIB)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) $(LDFLAGS) -fsanitize=fuzzer -o $@ $^ $(LDLIBS)

fuzz-targets: $(FUZZ_NAMES:%=$(BUILD)/fuzz/fuzz-%)

fuzz:
	$(MAKE) fuzz-targets CC=clang BUILD=$(BUILD)-fuzz \
	    OPT="-O1 -g -fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all" \
	    LDFLAGS="-fsanitize=address,undefined"

# Examples of the library's API (examples/*.c), each built as a program
# the way a user would: the public headers, librayo.a and the course's
# flags (C99, -Wall -Werror -pedantic).  `make check` builds them and
# tests/cli/examples.t runs them.
EXAMPLE_BIN := $(patsubst examples/%.c,$(BUILD)/examples/%,$(sort $(wildcard examples/*.c)))
check check-valgrind: $(EXAMPLE_BIN)

$(BUILD)/examples/%: examples/%.c $(LIB)
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(CC) -std=c99 -Wall -Werror -pedantic $(OPT) -Iinclude $(PNG_CFLAGS) \
	    $(CFLAGS) $(LDFLAGS) -o $@ $< $(LIB) $(LDLIBS)

# Benchmarks (bench/bench.c says how to add a row): a table on stdout
# and $(BUILD)/bench.json; docs/performance.md quotes them.
BENCH_BIN := $(BUILD)/bench/rayo-bench

$(BENCH_BIN): $(BENCH_SRC) bench/bench.h $(LIB)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) -Ibench $(LDFLAGS) -o $@ $(BENCH_SRC) $(LIB) \
	    $(LDLIBS)

# The peers' rows (bench/peers.c, docs/performance.md "Against Embree and
# POV-Ray") run $(BUILD)/bench/embree-rays, built only where Embree 3's
# header is (Debian's libembree-dev, no .pc file); rayo never links it.
# `make bench BENCH_ARGS="--only peers"` runs those rows alone.
EMBREE_HEADER ?= /usr/include/embree3/rtcore.h
EMBREE_LIBS ?= -lembree3
EMBREE_RAYS := $(BUILD)/bench/embree-rays
EMBREE_SRC := $(sort $(wildcard bench/embree/*.c))

$(EMBREE_RAYS): $(EMBREE_SRC) bench/embree/scene.h bench/embree/mesh.h \
    bench/embree/trace.h include/rayo/vec3.h | $(BUILD)/.deps-build
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $(EMBREE_SRC) $(EMBREE_LIBS) -lm

# `make check` builds it too where it can, for tests/cli/peers.t.
ifneq ($(wildcard $(EMBREE_HEADER)),)
check check-valgrind: $(EMBREE_RAYS)
endif

# The meshes of the bench's mesh rows (bench/meshes.c): a scan-like
# watertight STL and a scene framing it, written by bench/scan/scan_mesh.c
# into the build folder once (about 5, 50 and 500 MB).  `make bench
# BENCH_MESHES="100k 1m"` leaves the 10,000,000-triangle one out (its rows
# then say skipped).
SCAN_MESH := $(BUILD)/bench/scan-mesh
BENCH_MESHES ?= 100k 1m 10m
SCAN_COUNT_100k := 100000
SCAN_COUNT_1m := 1000000
SCAN_COUNT_10m := 10000000

$(SCAN_MESH): bench/scan/scan_mesh.c
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $< -lm

# Each step of a mesh's setup timed in process (bench/scan/setup_steps.c).
SETUP_STEPS := $(BUILD)/bench/setup-steps
setup-steps: $(SETUP_STEPS)
$(SETUP_STEPS): bench/scan/setup_steps.c $(LIB)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(CC) $(ALL_CFLAGS) $(LDFLAGS) -o $@ $< $(LIB) $(LDLIBS)

$(BUILD)/bench/scan-%.scene: $(SCAN_MESH)
	$(call say,GEN,$@)
	$(Q)$(SCAN_MESH) $(SCAN_COUNT_$*) $(BUILD)/bench/scan-$*.stl $@

bench: $(RAYO) $(BENCH_BIN) $(BENCH_MESHES:%=$(BUILD)/bench/scan-%.scene) \
    | $(BUILD)/.deps-bench
	@if [ -f $(EMBREE_HEADER) ]; then $(MAKE) --no-print-directory \
	    $(EMBREE_RAYS); else rm -f $(EMBREE_RAYS); echo "bench: no" \
	    "$(EMBREE_HEADER) (libembree-dev): the Embree rows say skipped"; fi
	RAYO=$(abspath $(RAYO)) RAYO_BUILD=$(abspath $(BUILD)) \
	RAYO_SOURCE=$(CURDIR) RAYO_BENCH_MESHES="$(BENCH_MESHES)" \
	    $(BENCH_BIN) --json $(BUILD)/bench.json \
	    $(BENCH_ARGS)

# The command tests with every rayo run under valgrind memcheck.
check-valgrind: all $(UNIT_BIN)
	RAYO_VALGRIND=1 RAYO=$(abspath $(RAYO)) RAYO_BUILD=$(abspath $(BUILD)) \
	RAYO_CC="$(CC) $(LDFLAGS)" RAYO_SOURCE=$(CURDIR) \
	    prove -f --exec '' $(sort $(wildcard tests/cli/*.t))

install: all
	install -d $(DESTDIR)$(PREFIX)/bin $(DESTDIR)$(PREFIX)/lib/pkgconfig \
	    $(DESTDIR)$(PREFIX)/include/rayo $(DESTDIR)$(PREFIX)/share/man/man1
	install -m 755 $(RAYO) $(DESTDIR)$(PREFIX)/bin/rayo
	install -m 644 $(LIB) $(DESTDIR)$(PREFIX)/lib/librayo.a
	install -m 755 $(SHLIB) $(DESTDIR)$(PREFIX)/lib/librayo.so.$(RAYO_VERSION)
	ln -sf librayo.so.$(RAYO_VERSION) $(DESTDIR)$(PREFIX)/lib/$(SO_NAME)
	ln -sf $(SO_NAME) $(DESTDIR)$(PREFIX)/lib/librayo.so
	install -m 644 include/rayo.h $(DESTDIR)$(PREFIX)/include/rayo.h
	install -m 644 include/rayo/*.h $(DESTDIR)$(PREFIX)/include/rayo/
	install -d $(DESTDIR)$(PREFIX)/include/rayo/course
	install -m 644 include/rayo/course/*.h $(DESTDIR)$(PREFIX)/include/rayo/course/
	install -m 644 man/rayo.1 $(DESTDIR)$(PREFIX)/share/man/man1/rayo.1
	for l in $(PO_LANGS); do \
	    install -d $(DESTDIR)$(PREFIX)/share/locale/$$l/LC_MESSAGES && \
	    install -m 644 $(BUILD)/locale/$$l/LC_MESSAGES/rayo.mo \
	        $(DESTDIR)$(PREFIX)/share/locale/$$l/LC_MESSAGES/rayo.mo \
	        || exit 1; done
	for m in man/*/rayo.1; do \
	    [ -f $$m ] || continue; \
	    l=$$(basename $$(dirname $$m)); \
	    install -d $(DESTDIR)$(PREFIX)/share/man/$$l/man1 && \
	    install -m 644 $$m $(DESTDIR)$(PREFIX)/share/man/$$l/man1/rayo.1 \
	        || exit 1; done
	install -d $(DESTDIR)$(PREFIX)/share/rayo/course
	install -m 644 data/course/*.png $(DESTDIR)$(PREFIX)/share/rayo/course/
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(RAYO_VERSION)|g' \
	    rayo.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/rayo.pc
	@case "$(DESTDIR):$(PREFIX)" in :/usr|:/usr/local) [ "$$(id -u)" != 0 ] \
	    || ! command -v ldconfig >/dev/null 2>&1 || ldconfig ;; esac

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/bin/rayo $(DESTDIR)$(PREFIX)/lib/librayo.a \
	    $(DESTDIR)$(PREFIX)/lib/librayo.so.$(RAYO_VERSION) \
	    $(DESTDIR)$(PREFIX)/lib/$(SO_NAME) $(DESTDIR)$(PREFIX)/lib/librayo.so \
	    $(DESTDIR)$(PREFIX)/include/rayo.h \
	    $(DESTDIR)$(PREFIX)/share/man/man1/rayo.1 \
	    $(DESTDIR)$(PREFIX)/lib/pkgconfig/rayo.pc \
	    $(PO_LANGS:%=$(DESTDIR)$(PREFIX)/share/locale/%/LC_MESSAGES/rayo.mo) \
	    $(patsubst man/%/rayo.1,$(DESTDIR)$(PREFIX)/share/man/%/man1/rayo.1,$(wildcard man/*/rayo.1))
	rm -rf $(DESTDIR)$(PREFIX)/include/rayo $(DESTDIR)$(PREFIX)/share/rayo

clean:
	rm -rf $(BUILD) $(BUILD)-sanitize $(BUILD)-fuzz esfera.pbm esfera.png

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)

# The page (web/, docs/web.md): the library compiled to WebAssembly with
# clang's wasm32-wasi target (Debian: clang, lld, wasi-libc,
# libclang-rt-*-dev-wasm32) into $(BUILD)/web/, a static site.  libpng,
# threads and files are the browser's business there: the library's
# sources build against web/wasm/include (pthread.h, png.h: libpng's
# writing calls, web/wasm/png_shim.c) in a configuration of their own,
# without files, libjpeg or libpng's reader (WASM_SWITCHES; the page
# uses rayo_output_open_memory and rayo_image_read_memory_with), and
# src/grade/ (which runs compilers) and output_target.c (the files'
# replacing) left out.  `make
# check-web` drives Chromium with Playwright (tests/web/); it skips when
# either is missing, and `make check` runs it when Chromium is installed.
WASM_CC ?= clang
# (wasi-libc's S_ISREG is a statement expression, which -pedantic flags.)
WASM_SWITCHES := -DRAYO_NO_FILE_OUTPUT -DRAYO_NO_JPEG -DRAYO_NO_PNG_READ
WASM_CFLAGS = --target=wasm32-wasi -std=c11 -O2 $(WARNINGS) \
              -Wno-gnu-statement-expression -Iweb/wasm/include -Iinclude \
              $(WASM_SWITCHES) -MMD -MP
WASM_LIB_SRC := $(filter-out src/io/output_target.c src/grade/% \
                 src/course/course_reference.c,$(LIB_SRC))
WASM_SRC := $(WASM_LIB_SRC) $(sort $(wildcard web/wasm/*.c))
WASM_OBJ := $(WASM_SRC:%.c=$(BUILD)/wasm/%.o) $(BUILD)/wasm/gen/catalogs.o
WEB_ASSETS := $(sort $(wildcard web/*.html web/*.js web/*.css))
WEB_OUT := $(BUILD)/web
CHROMIUM ?= $(shell command -v chromium chromium-browser 2>/dev/null | \
                head -n 1)

.PHONY: web check-web

WEB_WASM := $(BUILD)/wasm/rayo.wasm

web: $(WEB_OUT)/assets.js $(WEB_ASSETS:web/%=$(WEB_OUT)/%)

$(BUILD)/wasm/%.o: %.c | $(BUILD)/.deps-web
	@mkdir -p $(dir $@)
	$(call say,CC,$<)
	$(Q)$(WASM_CC) $(WASM_CFLAGS) -c $< -o $@

$(BUILD)/wasm/gen/catalogs.o: $(CATALOG_SRC) src/core/catalog.h
	@mkdir -p $(dir $@)
	$(WASM_CC) $(WASM_CFLAGS) -Isrc/core -c $< -o $@

$(WEB_WASM): $(WASM_OBJ)
	@mkdir -p $(dir $@)
	$(call say,LD,$@)
	$(Q)$(WASM_CC) --target=wasm32-wasi -O2 -nostartfiles -Wl,--no-entry \
	    -Wl,--strip-all -Wl,-z,stack-size=1048576 -o $@ $(WASM_OBJ) -lm

$(WEB_OUT)/%: web/%
	@mkdir -p $(dir $@)
	$(call say,CP,$@)
	$(Q)cp $< $@

# The fuzz targets that reach the module's code (reader, scene) replayed
# in WebAssembly, with its 32-bit size_t (tests/web/replay_wasm.mjs runs
# them under node's WASI; check-web does, docs/robustness.md).
WASM_FUZZ := $(patsubst %,$(BUILD)/wasm/fuzz/replay-%.wasm,reader scene)

$(BUILD)/wasm/fuzz/replay-%.wasm: $(BUILD)/wasm/fuzz/fuzz_%.o \
    $(BUILD)/wasm/fuzz/replay.o $(BUILD)/wasm/fuzz/refusal.o $(WASM_OBJ)
	@mkdir -p $(dir $@)
	$(WASM_CC) --target=wasm32-wasi -O2 -Wl,-z,stack-size=1048576 \
	    -o $@ $^ -lm

# The module and the course's references as base64 in a script, so the
# page fetches nothing and also works opened from file://.
$(WEB_OUT)/assets.js: $(WEB_WASM) $(COURSE_PNG)
	@mkdir -p $(dir $@)
	$(call say,GEN,$@)
	$(Q){ echo '// Made by make web: rayo.wasm and data/course/*.png, base64.'; \
	  echo 'window.RAYO_ASSETS = {'; \
	  printf '  "wasm": "%s",\n' "$$(base64 -w0 $(WEB_WASM))"; \
	  for f in $(COURSE_PNG); do \
	      n=$$(basename $$f .png | sed 's/.*-//'); \
	      printf '  "%s": "%s",\n' "$$n" "$$(base64 -w0 $$f)"; \
	  done; echo '};'; } > $@.tmp && mv $@.tmp $@

check-web: all
	@if [ -z "$(CHROMIUM)" ] || ! command -v node >/dev/null 2>&1 || \
	    [ ! -d tests/web/node_modules/playwright-core ] || \
	    ! printf '#include <stdio.h>\n' | $(WASM_CC) --target=wasm32-wasi \
	        -x c -c - -o /dev/null 2>/dev/null; then \
	    echo "1..0 # SKIP check-web: needs chromium, node, wasi-libc and" \
	         "'npm ci --prefix tests/web'"; \
	else \
	    $(MAKE) web $(WASM_FUZZ) && \
	    RAYO_SOURCE=$(CURDIR) node tests/web/replay_wasm.mjs \
	        $(abspath $(WASM_FUZZ)) && \
	    RAYO=$(abspath $(RAYO)) RAYO_WEB=$(abspath $(WEB_OUT)) \
	    RAYO_SOURCE=$(CURDIR) CHROMIUM=$(CHROMIUM) \
	        node tests/web/check.mjs; \
	fi

# (Not again in check-sanitize's run: the page's module is not built
# with the sanitizers.)
ifneq ($(CHROMIUM),)
ifeq ($(RAYO_SKIP_WEB),)
check: check-web
endif
endif

-include $(shell find $(BUILD)/wasm -name '*.d' 2>/dev/null)
