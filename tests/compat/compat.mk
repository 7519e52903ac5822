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

tests: $(COMPAT_BINS)
