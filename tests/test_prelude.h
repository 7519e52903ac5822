// tests/test_prelude.h — the headers most tests include, compiled once per build as a
// precompiled header (the Makefile passes it to every tests/*_test.cpp with -include).
// Parsing them is a third of compiling a small test; each test still includes what it
// uses itself, so it builds without this file too.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tiny3d.h"
