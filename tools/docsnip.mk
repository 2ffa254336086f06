# docsnip.mk: building and testing docsnip, which keeps the code excerpts in the docs true
# to the source. Included by tools/Makefile after common/build.mk; it needs nothing from
# common/, so it does not link libraytra.a.

.PHONY: docsnip docsnip-test
docsnip: $(BUILD)/docsnip
	@:

$(BUILD)/docsnip: $(BUILD)/docsnip.o
	$(CC) $(ALL_LDFLAGS) -o $@ $^

# The script writes its own fixtures into a temporary folder.
docsnip-test: $(BUILD)/docsnip
	@sh $(TOP)/tests/docsnip.sh $(BUILD)/docsnip
