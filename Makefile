# Makefile: builds, tests and demonstrates raytra: the library, every part of the course, the tools.
#
#   make             build everything
#   make test        run every test (unit tests, reference images, docs, layout)
#   make demo        render scenes/demo.scn with every part into out/
#   make references  re-render every part's reference images, showing what changed
#   make docs        refresh the code excerpts in docs/ from the source
#
# WERROR=1 turns warnings into errors; SANITIZE=1 builds and tests everything
# with AddressSanitizer and UndefinedBehaviorSanitizer.
include common/build.mk

PARTS    := $(sort $(notdir $(wildcard milestones/*)))
CHAPTERS := $(wildcard docs/*.md README.md milestones/*/README.md)
DOCSNIP  := $(TOOLS_DIR)/$(BUILD)/docsnip
LATEST   := milestones/$(lastword $(PARTS))/$(if $(filter 1,$(SANITIZE)),$(BUILD)/raytra,raytra)

.PHONY: all test demo references docs check-docs check-layout check-course clean
.NOTPARALLEL:

all:
	$(DEPS_STEP)
	@$(SUBMAKE) -C common
	@$(SUBMAKE) -C tools
	@for part in $(PARTS); do $(SUBMAKE) -C milestones/$$part || exit 1; done

test:
	$(DEPS_STEP) test
	@$(SUBMAKE) all
	@$(SUBMAKE) -C tests test
	@$(SUBMAKE) -C tools test
	@for part in $(PARTS); do $(SUBMAKE) -C milestones/$$part test || exit 1; done
	@$(SUBMAKE) check-docs check-layout check-course
	@echo "make test: every test passed"

# Every scene of the course's corpus (../shared/course-scenes) loads with the latest part.
check-course:
	@tests/course-scenes.sh check $(LATEST)

check-docs:
	@$(SUBMAKE) -C tools docsnip
	@$(DOCSNIP) --root . --check $(CHAPTERS) && echo "check-docs: every excerpt matches the source"

check-layout:
	@tools/check-layout.sh $(BUILD)

docs:
	@$(SUBMAKE) -C tools docsnip
	@$(DOCSNIP) --root . --update $(CHAPTERS)

demo: all
	@mkdir -p out
	@for part in $(PARTS); do \
	    milestones/$$part/raytra scenes/demo.scn out/demo-$$part.png || exit 1; \
	done
	@echo; echo "make demo: the demo scene as each part draws it:"; \
	for part in $(PARTS); do echo "    out/demo-$$part.png"; done

references:
	$(DEPS_STEP)
	@for part in $(PARTS); do $(SUBMAKE) -C milestones/$$part references || exit 1; done

clean:
	@$(SUBMAKE) -C common clean
	@$(SUBMAKE) -C tests clean
	@$(SUBMAKE) -C tools clean
	@for part in $(PARTS); do $(SUBMAKE) -C milestones/$$part clean; done
	rm -rf out
