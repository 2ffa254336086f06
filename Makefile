# Makefile: builds, tests and demonstrates raytra: the library, every part of the course, and
# the instructor's wings (compare/, sandbox/, grader/, platforms/, book/).
#
#   make             build everything
#   make test        run every test (unit tests, reference images, docs, layout)
#   make demo        render scenes/demo-tour.scn with every part, as each shows it best, into out/
#   make references  re-render every part's reference images, showing what changed
#   make install [PREFIX=/usr/local] [DESTDIR=]   install each part's renderer as
#                    raytra-1.1 ... raytra-1.6, imgdiff and mcstats as raytra-imgdiff and
#                    raytra-mcstats, and raytra-grade, which runs this checkout's grader,
#                    into DESTDIR/PREFIX/bin (make uninstall removes them)
#   make docs        refresh the code excerpts and generated tables in docs/ and grader/docs/ from the source
#   make starter PART=1.2 [DEST=dir]   write the starter of a part, the folder a course
#                    hands out, into out/starter-<part>/ (docs/starters.md)
#   make check-starter  the latest part's starter, every earlier part stubbed too: each
#                    marked function fails its tests as a stub and passes them solved (CI)
#   make check-starters  build every part's starter, stubbed and solved
#   make check-renders  every part renders every reference, project and course scene,
#                    and no pixel is NaN or infinite (a few minutes)
#   make check-interrupt  renders and loads stopped by signals, failed writes, a deep path
#                    under a small stack, some under valgrind (CI; a minute or so)
#   make valgrind    render scenes of every part, and broken inputs, under valgrind's memcheck
#   make bench       benchmark part 1.4's BVH against Embree 3 and tinybvh when they are there
#                    (TINYBVH=DIR: where tiny_bvh.h is; bench/README.md)
#   make fuzz        build the libFuzzer harnesses of the scene, OBJ and OpenEXR readers (clang)
#   make fuzz-run    fuzz each reader for FUZZ_SECONDS (default 1800) s (docs/fuzzing.md)
#   make mistakes    render the gallery of common mistakes and write docs/mistakes.md
#   make check-statistics  part 1.6's grading by statistics: right programs with 2 seeds pass,
#                    right and wrong solutions pass and fail (tests/mc-variants, a few minutes)
#   make calibrate-statistics  the statistical grading's false-fail rate over 350 seeds a
#                    scene and right program, 3,150 renders a scene (MC_COUNT, MC_OUT=DIR
#                    keeps the verdicts; some three hours on two idle cores)
#   make statistics-figure  draw the z-score heat maps grader/docs/statistics.md shows
#   make check-bvh-variants  part 1.4's grading: correct BVHs unlike raytra's pass every scene,
#                    wrong ones fail, saying why (tests/bvh-variants, a few minutes)
#   make check-mutation  each part's student functions mutated one change at a time, every
#                    mutant graded against the part's scenes: the mutation score, and no
#                    survivor unexplained (tests/mutation; MUTANTS=N grades N a part,
#                    PARTS_MUTATED= the parts; all of them, an hour or more)
#   make check-diagnosis  the grader's naming of the known mistake a failing image resembles,
#                    measured on mistakes kept out of its catalogue (tests/diagnosis; renders
#                    the mistakes first, make -C grader mistakes; ten minutes or more)
#   make check-slurm  grade a made-up class through platforms/slurm/grade-slurm on a Slurm cluster
#                    of one node it starts (as root; installs slurm-wlm and munge, or skips)
#   make gradescope PART=1.3 [OUT=file.zip]  write the part's Gradescope autograder, by
#                    default out/gradescope-<part>.zip (grader/docs/gradescope.md);
#                    GRADING_CONF=FILE, HIDDEN=DIR: points, visibility, hidden scenes
#   make check-gradescope  that autograder, unpacked and run on a correct, a buggy and an
#                    empty submission of part 1.3 (a few minutes)
#   make check-platforms  GitHub Classroom's, PrairieLearn's and CodeGrade's formats, converted
#                    from a tiny class's results, each valid in its platform's format
#                    (platforms/tests/formats.sh; installs jq, zip, unzip, xmllint and
#                    python3-jsonschema when missing; CI)
#   make check-contain  hostile submissions (processes left behind, a terminal's input,
#                    classmates' folders, a full disk, shared memory, copied references...)
#                    graded by grader/grade and run_autograder in both sandboxes, namespaces
#                    and the fallback: none reaches past its folder (as root for all of it;
#                    about 5 minutes)
#   make check-debian11  build, unit tests and that autograder in a Debian 11 root, whose
#                    OpenEXR 2.5 is Ubuntu 22.04's (as root; debootstrap; a few minutes)
#
# WERROR=1 turns warnings into errors; SANITIZE=1 builds and tests everything
# with AddressSanitizer and UndefinedBehaviorSanitizer.
include common/build.mk

PARTS    := $(sort $(notdir $(wildcard milestones/*)))
CHAPTERS := $(wildcard docs/*.md README.md */README.md milestones/*/README.md grader/docs/*.md)
DOCSNIP  := $(BOOK_DIR)/$(BUILD)/docsnip
# The program of part $1, as this build (normal or SANITIZE=1) makes it.
program   = milestones/$1/$(if $(filter 1,$(SANITIZE)),$(BUILD)/raytra,raytra)
LATEST   := $(call program,$(lastword $(PARTS)))
# Part 1.1 tests every sphere for every pixel: its renders are as long as a test needs.
FIRST    := $(call program,$(firstword $(PARTS)))
# The course corpus is rendered this much smaller: the parts before the BVH are brute force.
COURSE_SCALE ?= 0.05
FUZZ_SECONDS ?= 1800

.PHONY: all test test-others demo check-demo check-chromium references docs check-docs check-slides check-figures check-links check-layout check-course clean \
        check-robust check-fuzz-regressions check-bad-input check-interrupt check-nonfinite \
        check-course-render check-renders valgrind fuzz fuzz-run bench mistakes starter check-starter check-starter-chapter check-starters \
        check-exercises check-statistics calibrate-statistics check-bvh-variants check-mutation check-diagnosis statistics-figure gradescope \
        check-gradescope check-platforms check-slurm check-contain check-debian11 install uninstall check-help check-install

# Each folder is built by its own Makefile once what it links is built: common/ first, then
# compare/, the sandbox, the grader (which links both), the book's scripts and the parts (each
# after the parts it USES), side by side under make -j.
FOLDERS := common compare sandbox grader book $(PARTS:%=milestones/%)
.PHONY: deps $(FOLDERS)
all: $(FOLDERS)
	@:
deps:
	$(DEPS_STEP)
$(FOLDERS): deps
	+@$(SUBMAKE) -C $@
compare book $(PARTS:%=milestones/%): common
grader: compare sandbox
$(foreach part,$(PARTS),$(eval milestones/$(part): \
    $(addprefix milestones/,$(shell sed -n 's/^USES *:= *//p' milestones/$(part)/Makefile))))

# The grader's tests (make -C grader test) run beside all the others (test-others), their
# output held until the others' is done (tests/beside.sh): on two cores, a minute sooner.
test:
	$(DEPS_STEP) test
	+@$(SUBMAKE) all
	@echo "make test: the grader's tests (make -C grader test) run beside the others; their output comes last"
	+@tests/beside.sh "$(SUBMAKE) -C grader test" "$(SUBMAKE) test-others"
	@echo "make test: every test passed"

test-others:
	+@$(SUBMAKE) -C tests test
	+@$(SUBMAKE) -C compare test
	+@$(SUBMAKE) -C sandbox test
	+@$(SUBMAKE) -C book test
	+@for part in $(PARTS); do $(SUBMAKE) -C milestones/$$part test || exit 1; done
	+@$(SUBMAKE) -C book/mistakes
	+@$(SUBMAKE) check-docs check-slides check-figures check-links check-exercises check-layout check-course \
	            check-demo check-chromium
	+@$(SUBMAKE) check-starter-chapter check-help check-install
	+@$(SUBMAKE) check-fuzz-regressions check-bad-input

# Broken input of every kind and interruptions (docs/robustness-tests.md); make test runs the
# first two, CI the interruptions too (their stops under valgrind take half a minute or more).
check-robust: check-fuzz-regressions check-bad-input check-interrupt

# Every part renders every reference, project and course scene, with finite pixels: a few
# hundred renders, too many for make test; CI runs it (docs/robustness-tests.md).
check-renders: check-nonfinite check-course-render

# Every input the fuzzers ever crashed on, and their minimised corpora, loaded again.
check-fuzz-regressions:
	+@$(SUBMAKE) -C tests/fuzz regress

check-bad-input:
	@tests/bad-input.sh $(LATEST)

check-interrupt:
	@tests/interrupt.sh $(FIRST) $(LATEST)

check-nonfinite:
	@for part in $(PARTS); do \
	    tests/nonfinite.sh render $(call program,$$part) milestones/$$part/references || exit 1; \
	done

# Every part renders every scene of the corpus: none may fail or make a NaN pixel.
check-course-render:
	@for part in $(PARTS); do \
	    echo "== $$part"; \
	    tests/course-scenes.sh render $(call program,$$part) $(COURSE_SCALE) || exit 1; \
	done

valgrind:
	@if [ "$(SANITIZE)" = 1 ]; then echo "make valgrind: not with SANITIZE=1"; exit 2; fi
	+@$(SUBMAKE) all
	+@$(SUBMAKE) -C tests/fuzz regress-programs
	@tests/valgrind.sh $(PARTS:%=milestones/%)

fuzz:
	+@$(SUBMAKE) -C tests/fuzz fuzzers

# Speed, never part of make test: installs Embree 3 and a C++ compiler for the baselines when
# it can (tinybvh's header is not installed: it is ../shared/baselines/tinybvh, or TINYBVH=DIR).
bench:
	$(DEPS_STEP)
	@common/deps.sh bench || echo "bench: Embree 3 or a C++ compiler is missing: the baselines that need them will be skipped"
	+@$(SUBMAKE) -C bench run

fuzz-run: fuzz
	@tests/fuzz/run.sh scene $(FUZZ_SECONDS) && tests/fuzz/run.sh obj $(FUZZ_SECONDS) && \
	    tests/fuzz/run.sh exr $(FUZZ_SECONDS)

# The README's pictures of the parts are the images make demo writes, byte for byte.
check-demo:
	@tests/readme-images.sh "$(MAKE)"

# common/deps.sh finds Chromium, which grader/tests/grade-report.sh runs, by each of its names.
check-chromium:
	@tests/chromium-lookup.sh

# Every scene of the course's corpus (../shared/course-scenes) loads with the latest part.
check-course:
	@tests/course-scenes.sh check $(LATEST)

# The docs' tool outputs come from runs of the programs (book/doctables.sh): built first.
DOCTABLES := BUILD=$(BUILD) RAYTRA_PROGRAM=$(if $(filter 1,$(SANITIZE)),$(BUILD)/raytra,raytra) \
             book/doctables.sh
check-docs:
	+@$(SUBMAKE) all
	+@$(SUBMAKE) -C book/mistakes
	+@$(SUBMAKE) -C book docsnip
	@$(DOCSNIP) --root . --check $(CHAPTERS) && echo "check-docs: every excerpt matches the source"
	@$(DOCTABLES) --check
	@book/marked.sh check-explain && echo "check-docs: no function a student writes prints to --trace-pixel"

# Every SVG of docs/figures is well-formed with a viewBox; every figure linked to exists.
check-figures:
	@tests/figures.sh

# Every relative link of the chapters and READMEs leads to a file, and each #anchor to a heading.
check-links:
	@tests/links.sh

check-layout:
	@book/check-layout.sh $(BUILD)

# Every pixel answer of the chapters' exercises agrees with a render (docs/exercises-answers.md).
check-exercises:
	@RAYTRA_PROGRAM=$(if $(filter 1,$(SANITIZE)),$(BUILD)/raytra,raytra) scenes/exercises/check.sh

# A part's starter for students: STARTER_OPTIONS may say --stub-earlier, --solution or
# --docs-url URL. PART is one word (PART="1.2 1.3" would make 1.3 the DEST); DEST is quoted.
starter:
	@if [ -z "$(PART)" ]; then echo "usage: make starter PART=1.2 [DEST=dir]" >&2; exit 2; fi
	@if [ $(words $(PART)) -ne 1 ]; then echo "make starter: PART is one part (PART=1.2), got" \
	    "'$(PART)': make one starter at a time" >&2; exit 2; fi
	$(DEPS_STEP)
	@book/starter.sh --chapter $(STARTER_OPTIONS) '$(PART)' $(if $(DEST),'$(subst ','\'',$(DEST))')

# The starter of the latest part with every earlier part stubbed too: each marked function
# of the project in one build, failing its tests as a stub and passing them when solved.
check-starter:
	@tests/starter.sh --stub-earlier $(lastword $(PARTS))

# The student edition of part 1.4's chapter (book/starter.sh --chapter): its marked
# functions as stubs, nothing else changed; tests/starter-chapter.sh 1.1 ... 1.6 tries all.
check-starter-chapter:
	@tests/starter-chapter.sh 1.4

# Each part's starter as a course hands it out, the earlier parts complete.
check-starters: check-starter
	@tests/starter.sh $(PARTS)

# Every "slide N" in the project quotes words that stand on slide N of the lecture.
check-slides:
	@tests/slides.sh

docs:
	+@$(SUBMAKE) all
	+@$(SUBMAKE) -C book/mistakes
	+@$(SUBMAKE) -C book docsnip
	@$(DOCSNIP) --root . --update $(CHAPTERS)
	@$(DOCTABLES) --update

# Each part renders the demo scene as the line of its references/renders.txt that names
# the scene says (part 1.4 draws its BVH's leaf boxes, part 1.6 takes P = 2 and S = 2), so
# that each shows what it adds; the README shows those references, and check-demo checks
# that they are the very files make demo writes.
DEMO_SCENE := scenes/demo-tour.scn
DEMO_DIR   ?= out
demo: all
	@mkdir -p $(DEMO_DIR)
	@for part in $(PARTS); do \
	    options=$$(awk -v scene=$(DEMO_SCENE) '$$2 == scene { $$1 = $$2 = ""; sub(/^ */, ""); \
	               print; found = 1; exit } END { exit !found }' milestones/$$part/references/renders.txt) || \
	        { echo "make demo: no line for $(DEMO_SCENE) in milestones/$$part/references/renders.txt" >&2; \
	          exit 1; }; \
	    echo "== $(call program,$$part) $(DEMO_SCENE) $(DEMO_DIR)/demo-$$part.png $$options"; \
	    $(call program,$$part) $(DEMO_SCENE) $(DEMO_DIR)/demo-$$part.png $$options || exit 1; \
	done
	@echo; echo "make demo: $(DEMO_SCENE) as each part draws it:"; \
	for part in $(PARTS); do echo "    $(DEMO_DIR)/demo-$$part.png"; done

# The gallery of common mistakes: part 1.3 with one function broken at a time.
mistakes: all
	+@$(SUBMAKE) -C book/mistakes
	@book/mistakes/gallery.sh

# Monte Carlo renders judged by statistics (grader/docs/statistics.md): right programs
# (raytra and other generators and schemes) with MC_SEEDS seeds of their own each pass,
# each variant of part 1.6 (tests/mc-variants) passes or fails as it should; first,
# calibrate.sh's progress lines, with stand-ins for the programs (progress.sh).
MC_PART := milestones/1.6-monte-carlo
MC_SEEDS ?= 2
check-statistics:
	$(DEPS_STEP)
	+@$(SUBMAKE) all
	+@$(SUBMAKE) -C tests/mc-variants
	@sh tests/mc-variants/progress.sh
	@tests/mc-variants/calibrate.sh $(call program,1.6-monte-carlo) tests/mc-variants/$(BUILD) \
	    $(MC_PART)/references $(MC_SEEDS)
	@tests/mc-variants/run.sh $(call program,1.6-monte-carlo) tests/mc-variants/$(BUILD) \
	    $(IMGDIFF) $(MC_PART)/references

# Part 1.4 graded on BVHs unlike raytra's (grader/docs/bvh-judging.md): each variant of
# tests/bvh-variants, right or wrong, passes or fails as it should, with the reason.
check-bvh-variants:
	$(DEPS_STEP)
	+@$(SUBMAKE) all
	+@$(SUBMAKE) -C tests/bvh-variants
	@tests/bvh-variants/run.sh $(GRADER_DIR)/$(BUILD)/grade tests/bvh-variants/$(BUILD)

# The graded scenes measured by mutation (grader/docs/mutation.md): each mutant of a part's
# student functions, graded like a student, is caught by a scene or known to be equivalent.
MUTANTS ?= 0
PARTS_MUTATED ?= $(PARTS)
check-mutation:
	$(DEPS_STEP)
	+@$(SUBMAKE) all
	@tests/mutation/run.sh --sample $(MUTANTS) $(PARTS_MUTATED)
# The grader's diagnosis (grader/docs/diagnosis.md): each part's known mistakes rendered, then
# a class of the catalogue's mistakes, mistakes kept out of it, and correct programs graded;
# the table of what was named goes to DIAGNOSIS_TABLE when given.
check-diagnosis:
	$(DEPS_STEP)
	+@$(SUBMAKE) all
	+@$(SUBMAKE) -C grader mistakes
	+@$(SUBMAKE) -C tests/bvh-variants VARIANT_DIR=../diagnosis/held-out-1.4 \
	    VARIANT_OUT=../diagnosis/$(BUILD)/held-out-1.4
	@failed=0; \
	tests/diagnosis/run.sh $(GRADER_DIR)/$(BUILD)/grade 1.4-bvh tests/diagnosis/1.4-bvh.txt \
	    $(DIAGNOSIS_TABLE) || failed=1; \
	tests/diagnosis/run.sh $(GRADER_DIR)/$(BUILD)/grade 1.6-monte-carlo \
	    tests/diagnosis/1.6-monte-carlo.txt || failed=1; \
	exit $$failed

# The false-fail rate of the statistical grading, measured: MC_COUNT seeds (default 350)
# of each of the nine right programs and graded scene, in PNG, PFM and EXR (hours).
MC_COUNT ?= 350
calibrate-statistics:
	$(DEPS_STEP)
	+@$(SUBMAKE) all
	+@$(SUBMAKE) -C tests/mc-variants
	@nice -n 10 tests/mc-variants/calibrate.sh $(call program,1.6-monte-carlo) \
	    tests/mc-variants/$(BUILD) $(MC_PART)/references $(MC_COUNT) $(MC_OUT)

# A class graded on Slurm (grader/docs/at-scale.md): shards and a merge, on a cluster of
# one node started and stopped by the test, give the report that one run of grade gives.
check-slurm:
	$(DEPS_STEP)
	+@$(SUBMAKE) -C grader SANITIZE=0
	+@$(SUBMAKE) -C milestones/1.1-spheres-red SANITIZE=0
	@platforms/tests/slurm.sh milestones/1.1-spheres-red/raytra

# A part's Gradescope autograder: a zip with setup.sh and run_autograder at its root.
# PART is one word, as for a starter; OUT is quoted.
gradescope:
	@if [ -z "$(PART)" ]; then echo "usage: make gradescope PART=1.3 [OUT=file.zip]" >&2; exit 2; fi
	@if [ $(words $(PART)) -ne 1 ]; then echo "make gradescope: PART is one part (PART=1.3)," \
	    "got '$(PART)'" >&2; exit 2; fi
	@common/deps.sh gradescope
	@platforms/gradescope/pack.sh '$(PART)' $(if $(OUT),'$(subst ','\'',$(OUT))')

# The autograder of part 1.3 unpacked, set up and run as Gradescope would, on a correct, a
# buggy, an empty and a hostile submission (platforms/tests/gradescope.sh); not part of make test.
check-gradescope:
	@common/deps.sh gradescope-test
	@platforms/tests/gradescope.sh

# The converters of platforms/ (GitHub Classroom, PrairieLearn, CodeGrade) on a tiny class of
# part 1.1: each output valid against its platform's published format (grader/docs/platforms.md).
check-platforms:
	$(DEPS_STEP)
	@common/deps.sh platforms-test
	+@$(SUBMAKE) -C grader SANITIZE=0
	@platforms/tests/formats.sh grader/build/grade

# Hostile submissions, each of a way out of its folder: contained by grader/grade (as a user,
# and as root with --run-as) and by run_autograder, in bubblewrap's namespaces and in the
# fallback (grader/tests/contain.sh).
check-contain:
	$(DEPS_STEP)
	@common/deps.sh gradescope-test
	+@$(SUBMAKE) -C grader SANITIZE=0
	+@$(SUBMAKE) -C milestones/1.1-spheres-red SANITIZE=0
	@grader/tests/contain.sh grader/build/grade

# OpenEXR 2 (Ubuntu 22.04, Gradescope's newest image) as well as 3: in a Debian 11 root.
check-debian11:
	@tests/debian11.sh

# The figures of the statistical grading (grader/docs/statistics.md, chapter 1.6): z-score
# heat maps.
statistics-figure:
	+@$(SUBMAKE) all
	+@$(SUBMAKE) -C tests/mc-variants
	@tests/mc-variants/figure.sh $(call program,1.6-monte-carlo) tests/mc-variants/$(BUILD) \
	    $(IMGDIFF) $(MC_PART)/references docs/figures/1.6-monte-carlo

# The programs that stand alone: each part's renderer, and compare/'s two; and the grader as
# raytra-grade, a script that runs this checkout's grader/grade, since the grader grades
# from its checkout, whose references and scenes it reads.
PREFIX ?= /usr/local
BINDIR ?= $(PREFIX)/bin
INSTALLED := $(foreach part,$(PARTS),raytra-$(firstword $(subst -, ,$(part)))) raytra-imgdiff \
             raytra-mcstats raytra-grade
install: all
	install -d '$(DESTDIR)$(BINDIR)'
	@for part in $(PARTS); do \
	    echo "install $(call program,$$part) $(DESTDIR)$(BINDIR)/raytra-$${part%%-*}"; \
	    install -m 755 $(call program,$$part) '$(DESTDIR)$(BINDIR)'/raytra-$${part%%-*} || exit 1; \
	done
	install -m 755 $(IMGDIFF) '$(DESTDIR)$(BINDIR)/raytra-imgdiff'
	install -m 755 $(COMPARE_DIR)/$(BUILD)/mcstats '$(DESTDIR)$(BINDIR)/raytra-mcstats'
	printf '#!/bin/sh\n# raytra-grade: the grader of the raytra checkout at %s.\nexec %s "$$@"\n' \
	    '$(TOP)' '$(TOP)/grader/grade' >'$(DESTDIR)$(BINDIR)/raytra-grade'
	chmod 755 '$(DESTDIR)$(BINDIR)/raytra-grade'

uninstall:
	cd '$(DESTDIR)$(BINDIR)' && rm -f $(INSTALLED)

# Every program and script a user runs answers --help; make install and uninstall into a
# temporary DESTDIR, and the installed renderers run from there.
check-help:
	@tests/help.sh $(BUILD)

check-install:
	@tests/install.sh "$(MAKE)"

references:
	$(DEPS_STEP)
	+@for part in $(PARTS); do $(SUBMAKE) -C milestones/$$part references || exit 1; done

clean:
	+@$(SUBMAKE) -C common clean
	+@$(SUBMAKE) -C tests clean
	+@$(SUBMAKE) -C tests/fuzz clean
	+@$(SUBMAKE) -C compare clean
	+@$(SUBMAKE) -C sandbox clean
	+@$(SUBMAKE) -C grader clean
	+@$(SUBMAKE) -C book clean
	+@$(SUBMAKE) -C bench clean
	+@$(SUBMAKE) -C book/mistakes clean
	+@$(SUBMAKE) -C tests/mc-variants clean
	+@$(SUBMAKE) -C tests/bvh-variants clean
	+@for part in $(PARTS); do $(SUBMAKE) -C milestones/$$part clean; done
	rm -rf out
