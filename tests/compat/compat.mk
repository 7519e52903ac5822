# tests/compat/compat.mk — included by the Makefile (after the test rules).
# The user-style programs tests/compat/*.c are compiled AS C++ the way their users build
# them: g++ -std=c++20 -Wall -Wextra -Werror (no -Wpedantic: compound literals), linked
# with $(LIB). `make tests` builds them into $(BUILD)/compat/; tests/compat_test.cpp runs
# them (BUILD from the environment) and checks their output.
COMPAT_SRCS  := $(sort $(wildcard tests/compat/*.c))
COMPAT_BINS  := $(COMPAT_SRCS:tests/compat/%.c=$(BUILD)/compat/%)
COMPAT_FLAGS := -std=c++20 -Wall -Wextra -Werror

$(BUILD)/compat/%: tests/compat/%.c $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(COMPAT_FLAGS) $(CPPFLAGS) -MF $@.d -MT $@ -x c++ $< -x none $(LIB) -o $@ $(LDLIBS)

tests: $(COMPAT_BINS)
