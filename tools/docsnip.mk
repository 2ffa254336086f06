# docsnip.mk: docsnip, which keeps the code excerpts in the docs true to the source: a POSIX
# sh and awk script (docsnip.sh), put where the Makefiles run it. Included by tools/Makefile.

.PHONY: docsnip docsnip-test
docsnip: $(BUILD)/docsnip
	@:

$(BUILD)/docsnip: docsnip.sh
	@mkdir -p $(BUILD)
	cp docsnip.sh $@
	chmod +x $@

# The script writes its own fixtures into a temporary folder.
docsnip-test: $(BUILD)/docsnip
	@sh $(TOP)/tests/docsnip.sh $(BUILD)/docsnip
