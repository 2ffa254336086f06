# build.mk: compiler settings and rules shared by every Makefile of raytra.
#
# Variables a caller may set on the command line or in the environment:
#   WERROR=1    treat warnings as errors (CI does)
#   SANITIZE=1  build with AddressSanitizer and UndefinedBehaviorSanitizer,
#               into build-sanitize/ so that normal objects stay untouched
#   CC, OPT, CFLAGS, LDFLAGS   compiler, optimisation and extra flags

TOP := $(abspath $(dir $(lastword $(MAKEFILE_LIST)))..)

# clang writes DWARF 5 by default, which valgrind 3.19 (Debian 12's) cannot read: DWARF 4.
OPT ?= -O2 -g $(if $(findstring clang,$(CC)),-gdwarf-4)

WARNINGS := -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes \
            -Wmissing-prototypes
ifeq ($(WERROR),1)
WARNINGS += -Werror
endif

ifeq ($(SANITIZE),1)
BUILD    := build-sanitize
SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all \
            -fno-omit-frame-pointer
else
BUILD    := build
SANFLAGS :=
endif

# pkg-config (PKG_CONFIG) is asked once, and only when a recipe needs the answer, so that
# the deps step can install a missing pkg-config first (see common/deps.sh).
PKG_CONFIG ?= pkg-config
lazy = $(eval $1 := $$(shell $2))$($1)
PNG_CFLAGS   = $(call lazy,PNG_CFLAGS,$(PKG_CONFIG) --cflags libpng 2>/dev/null)
PNG_LIBS     = $(call lazy,PNG_LIBS,$(PKG_CONFIG) --libs libpng 2>/dev/null || echo -lpng -lz)
# raytra writes OpenEXR itself, on zlib (docs/architecture.md); the tools read what their own
# reader does not through OpenEXR's C interface to RGBA files (exr_rgba.c), the same in
# OpenEXR 2 and 3. A student's starter has exr_rgba_none.c instead, and needs no OpenEXR.
ZLIB_CFLAGS  = $(call lazy,ZLIB_CFLAGS,$(PKG_CONFIG) --cflags zlib 2>/dev/null)
ZLIB_LIBS    = $(call lazy,ZLIB_LIBS,$(PKG_CONFIG) --libs zlib 2>/dev/null || echo -lz)
EXR_RGBA    := $(if $(wildcard $(TOP)/compare/exr_rgba.c),exr_rgba,exr_rgba_none)
EXR_CFLAGS   = $(call lazy,EXR_CFLAGS,$(PKG_CONFIG) --cflags OpenEXR 2>/dev/null || echo -I/usr/include/OpenEXR)
EXR_LIBS     = $(if $(filter exr_rgba,$(EXR_RGBA)),$(call lazy,EXR_LIBS,$(PKG_CONFIG) --libs OpenEXR 2>/dev/null || echo -lOpenEXR))
# What a program that links libraytra.a links for its image files; a tool that reads them
# links TOOL_IMAGE_LIBS.
IMAGE_LIBS   = $(PNG_LIBS) $(ZLIB_LIBS)
TOOL_IMAGE_LIBS = $(IMAGE_LIBS) $(EXR_LIBS)
CHECK_CFLAGS = $(call lazy,CHECK_CFLAGS,$(PKG_CONFIG) --cflags check 2>/dev/null)
CHECK_LIBS   = $(call lazy,CHECK_LIBS,$(PKG_CONFIG) --libs check 2>/dev/null || echo -lcheck -lsubunit -lm)

ALL_CPPFLAGS = -D_XOPEN_SOURCE=700 -MMD -MP $(INCLUDES) $(CPPFLAGS)
ALL_CFLAGS   = -std=c11 $(OPT) $(WARNINGS) $(SANFLAGS) -pthread $(CFLAGS)
ALL_LDFLAGS  = $(SANFLAGS) -pthread $(LDFLAGS)

COMMON_DIR := $(TOP)/common
COMMON_LIB := $(COMMON_DIR)/$(BUILD)/libraytra.a
COMPARE_DIR := $(TOP)/compare
GRADER_DIR  := $(TOP)/grader
SANDBOX_DIR := $(TOP)/sandbox
SANDBOX_LIB := $(SANDBOX_DIR)/$(BUILD)/libsandbox.a
BOOK_DIR    := $(TOP)/book
IMGDIFF     := $(COMPARE_DIR)/$(BUILD)/imgdiff

# The deps step installs (or names) missing packages once per top-level make;
# sub-makes started through $(SUBMAKE) skip it.
ifdef RAYTRA_DEPS_OK
DEPS_STEP = @true
else
DEPS_STEP = @CC='$(CC)' PKG_CONFIG='$(PKG_CONFIG)' $(TOP)/common/deps.sh
endif
SUBMAKE = $(MAKE) --no-print-directory RAYTRA_DEPS_OK=1

# Check stops a test after 4 s by default: too short under the sanitizers or valgrind.
export CK_DEFAULT_TIMEOUT ?= 300

# Compiling one C file into the build folder.
$(BUILD)/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(ALL_CPPFLAGS) $(ALL_CFLAGS) -c $< -o $@
