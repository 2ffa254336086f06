# grade.mk: building and testing grade, which grades a class's submissions against a part's
# reference images (docs/grading.md). Included by tools/Makefile after common/build.mk.

GRADE         := $(BUILD)/grade
# The parts' tables of options, compiled here alone: grade passes a part's positional
# arguments (1.4's MODE, 1.6's P and S) to students' programs, and only those.
PART_OPTIONS  := shade_options.c trace_options.c accel_options.c refract_options.c \
                 montecarlo_options.c
GRADE_OBJECTS := $(addprefix $(BUILD)/,grade.o grade_part.o grade_submission.o grade_run.o grade_report.o \
                   grade_jobs.o grade_contain.o grade_reap.o grade_sandbox.o grade_shard.o grade_merge.o grade_export.o \
                   imgfile.o toolopt.o part_options.o) $(PART_OPTIONS:%.c=$(BUILD)/%.o)
PART_DIRS     := $(wildcard $(TOP)/milestones/*)
vpath %_options.c $(PART_DIRS)
$(BUILD)/part_options.o $(PART_OPTIONS:%.c=$(BUILD)/%.o) $(BUILD)/grade_part.o: \
    INCLUDES += $(PART_DIRS:%=-I%)
# The test's model of a correct submission runs part 1.1's program, built without the
# sanitizers: their shadow memory does not fit under the grader's memory limit.
GRADE_PART    := $(TOP)/milestones/1.1-spheres-red

.PHONY: grade grade-test report-figure
grade: $(GRADE) $(IMGDIFF)
	@:

$(GRADE): $(GRADE_OBJECTS) $(IMAGE_READER) $(COMMON_LIB)
	$(CC) $(ALL_LDFLAGS) -o $@ $^ $(TOOL_IMAGE_LIBS) -lm

# The script makes its class of submissions in a temporary folder; every part's program is
# also graded as a student's, against its own references.
grade-test: $(GRADE) $(IMGDIFF)
	@for part in $(wildcard $(TOP)/milestones/*/Makefile); do \
	    $(SUBMAKE) -C $$(dirname $$part) SANITIZE=0 || exit 1; done
	@sh $(TOP)/tests/grade.sh $(GRADE) $(GRADE_PART)/raytra
	@sh $(TOP)/tests/grade-judges.sh $(GRADE)
	@sh $(TOP)/tests/grade-report.sh $(GRADE) $(GRADE_PART)/raytra
	@sh $(TOP)/tests/grade-class.sh $(GRADE) $(GRADE_PART)/raytra
	@sh $(TOP)/tests/junit.sh $(GRADE)

# The report's picture in docs/grading.md: a made-up class's report, checked in Chromium,
# then photographed by it.
report-figure: $(GRADE) $(IMGDIFF)
	@$(SUBMAKE) -C $(GRADE_PART) SANITIZE=0
	@sh $(TOP)/tests/grade-report.sh $(GRADE) $(GRADE_PART)/raytra \
	    --figure $(TOP)/docs/figures/grading-report.png

# The report's style sheet, kept as CSS and compiled in as a C string, a line a line of the
# file but the first, which says what the file is: the report stays one self-contained page.
$(BUILD)/grade_style.h: grade_report.css grade.mk
	@mkdir -p $(BUILD)
	sed '1d; s/[\\"]/\\&/g; s/.*/"&\\n"/' $< >$@
$(BUILD)/grade_report.o: $(BUILD)/grade_style.h
$(BUILD)/grade_report.o: INCLUDES += -I$(BUILD)
