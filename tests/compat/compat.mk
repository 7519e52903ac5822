# tests/compat/compat.mk — included by the Makefile (after the test rules).
# The user-style programs are compiled AS C++ the way their users build them: g++
# -std=c++20 -Wall -Wextra -Werror (no -Wpedantic: compound literals), linked with $(LIB).
# Each tests/compat/NAME.c is one program, and so is each folder tests/compat/NAME/ (all its
# .c files, compiled separately and linked together). `make tests` builds them into
# $(BUILD)/compat/; tests/compat_test.cpp and tests/compat_names_test.cpp run them (BUILD
# from the environment) and check their output.
COMPAT_SRCS  := $(sort $(wildcard tests/compat/*.c))
COMPAT_DIRS  := $(sort $(patsubst tests/compat/%/,%,$(dir $(wildcard tests/compat/*/*.c))))
COMPAT_BINS  := $(COMPAT_SRCS:tests/compat/%.c=$(BUILD)/compat/%) $(COMPAT_DIRS:%=$(BUILD)/compat/%)
COMPAT_FLAGS := -std=c++20 -Wall -Wextra -Werror

$(BUILD)/compat/%: tests/compat/%.c $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(COMPAT_FLAGS) $(CPPFLAGS) -MF $@.d -MT $@ -x c++ $< -x none $(LIB) -o $@ $(LDLIBS)

$(BUILD)/compat/obj/%.o: tests/compat/%.c
	@mkdir -p $(@D)
	$(CXX) $(COMPAT_FLAGS) $(CPPFLAGS) -MF $@.d -MT $@ -x c++ -c $< -o $@

define compat-folder-program
$(BUILD)/compat/$(1): $(patsubst tests/compat/%.c,$(BUILD)/compat/obj/%.o,$(sort $(wildcard tests/compat/$(1)/*.c))) $(LIB)
	$$(CXX) $$(filter %.o,$$^) $(LIB) -o $$@ $(LDLIBS)
endef
$(foreach d,$(COMPAT_DIRS),$(eval $(call compat-folder-program,$(d))))

# ---- the same programs as C ----
COMPAT_C_NAMES := c_names lit_bezier own_forms own_helpers report_demo
COMPAT_CC      ?= gcc
COMPAT_C_FLAGS_c11 := -std=c11 -Wall -Wextra -Wpedantic -Werror
COMPAT_C_FLAGS_gnu := -Wall -Wextra -Werror
COMPAT_C_LIBS  := -lstdc++ -lm -pthread
COMPAT_C_BINS  := $(foreach v,c11 gnu,$(COMPAT_C_NAMES:%=$(BUILD)/compat/$(v)/%))

define compat-c-variant
$(BUILD)/compat/$(1)/%: tests/compat/%.c $(LIB)
	@mkdir -p $$(@D)
	$(COMPAT_CC) $(COMPAT_C_FLAGS_$(1)) $$(CPPFLAGS) -MF $$@.d -MT $$@ $$< $(LIB) -o $$@ $(COMPAT_C_LIBS)

$(BUILD)/compat/$(1)/obj/%.o: tests/compat/%.c
	@mkdir -p $$(@D)
	$(COMPAT_CC) $(COMPAT_C_FLAGS_$(1)) $$(CPPFLAGS) -MF $$@.d -MT $$@ -c $$< -o $$@
endef
$(foreach v,c11 gnu,$(eval $(call compat-c-variant,$(v))))

define compat-c-folder-program
$(BUILD)/compat/$(2)/$(1): $(patsubst tests/compat/%.c,$(BUILD)/compat/$(2)/obj/%.o,$(sort $(wildcard tests/compat/$(1)/*.c))) $(LIB)
	$(COMPAT_CC) $$(filter %.o,$$^) $(LIB) -o $$@ $(COMPAT_C_LIBS)
endef
$(foreach v,c11 gnu,$(foreach d,$(filter $(COMPAT_DIRS),$(COMPAT_C_NAMES)),$(eval $(call compat-c-folder-program,$(d),$(v)))))

tests: $(COMPAT_BINS) $(COMPAT_C_BINS)
