# milestone.mk: how every part of the course is built and tested; milestones/*/Makefile include it.
#
# The including Makefile sets, before the include:
#   USES     the earlier parts whose code this part links, newest first
#   SOURCES  this part's own modules (everything but raytra.c, which holds main)
#   TESTS    its Check unit tests, tests/test_*.c
# A part's modules go into its library $(BUILD)/libpart.a; raytra links raytra.c
# with that library, the libraries of the parts it uses, and common's.
include $(dir $(lastword $(MAKEFILE_LIST)))build.mk

PART       := $(notdir $(CURDIR))
LIB        := $(BUILD)/libpart.a
USED_DIRS  := $(USES:%=$(TOP)/milestones/%)
USED_LIBS  := $(USED_DIRS:%=%/$(BUILD)/libpart.a)
OBJECTS    := $(SOURCES:%.c=$(BUILD)/%.o)
TEST_PROGS := $(TESTS:%.c=$(BUILD)/%)
PROGRAM    := $(if $(filter 1,$(SANITIZE)),$(BUILD)/raytra,raytra)
INCLUDES    = -I. $(USED_DIRS:%=-I%) -I$(COMMON_DIR) $(PNG_CFLAGS)
LINK_LIBS   = $(LIB) $(USED_LIBS) $(COMMON_LIB)

.PHONY: all lib test unit-test image-test references prerequisites test-programs clean
.SECONDARY:
all: $(PROGRAM)
	@:
lib: $(LIB)
	@:
test-programs: $(TEST_PROGS)
	@:

# The libraries of common/ and of the parts used are built by their own Makefiles.
prerequisites:
	$(DEPS_STEP)
	+@$(SUBMAKE) -C $(COMMON_DIR) lib
	+@for dir in $(USED_DIRS); do $(SUBMAKE) -C $$dir lib || exit 1; done
$(COMMON_LIB) $(USED_LIBS): prerequisites ;

$(LIB): $(OBJECTS)
	@mkdir -p $(dir $@)
	rm -f $@
	$(AR) rcs $@ $^

$(PROGRAM): $(BUILD)/raytra.o $(LINK_LIBS)
	$(CC) $(ALL_LDFLAGS) -o $@ $< $(LINK_LIBS) $(IMAGE_LIBS) -lm

$(BUILD)/tests/%: $(BUILD)/tests/%.o $(LINK_LIBS)
	$(CC) $(ALL_LDFLAGS) -o $@ $< $(LINK_LIBS) $(CHECK_LIBS) $(IMAGE_LIBS) -lm
$(BUILD)/tests/%.o: INCLUDES += -I$(TOP)/tests $(CHECK_CFLAGS) -DPART_DIR='"$(CURDIR)"' \
                                 -DTOP_DIR='"$(TOP)"' -DRAYTRA='"$(CURDIR)/$(PROGRAM)"'

test: unit-test image-test

# Unit tests may run the part's program on a scene, so it is built first; each test
# runs in a scratch folder of its own, removed when it passes.
unit-test:
	$(DEPS_STEP) test
	+@$(SUBMAKE) test-programs $(PROGRAM)
	@for t in $(TEST_PROGS); do \
	    echo "== $(PART): $$t"; scratch=$$(mktemp -d); \
	    (cd $$scratch && $(CURDIR)/$$t) || { echo "FAILED: $$t (scratch kept in $$scratch)"; exit 1; }; \
	    rm -rf $$scratch; \
	done

# Renders every reference scene, compares it with the committed image and checks
# that 1 and 2 threads give the same bytes (tests/regress.sh); the same for the
# figures of the part's chapter, in docs/figures/<part>/, when it has some.
FIGURES    := $(wildcard $(TOP)/docs/figures/$(PART)/renders.txt)
IMAGE_SETS := references $(FIGURES:%/renders.txt=%)

image-test: $(PROGRAM)
	+@$(SUBMAKE) -C $(COMPARE_DIR) imgdiff
	@for set in $(IMAGE_SETS); do \
	    $(TOP)/tests/regress.sh check $(CURDIR)/$(PROGRAM) $(IMGDIFF) $$set || exit 1; done

references: $(PROGRAM)
	+@$(SUBMAKE) -C $(COMPARE_DIR) imgdiff
	@for set in $(IMAGE_SETS); do \
	    $(TOP)/tests/regress.sh update $(CURDIR)/$(PROGRAM) $(IMGDIFF) $$set || exit 1; done

clean:
	rm -rf build build-sanitize raytra

-include $(OBJECTS:.o=.d) $(BUILD)/raytra.d $(TEST_PROGS:%=%.d)
