// Precompiled for every GoogleTest program (tests/CMakeLists.txt, ARMTRACK_TEST_PCH): the
// third-party and standard headers most of them include, parsed once per build instead of once
// per test. Only headers that do not depend on the project's own macros belong here; a test
// still includes what it uses, so it builds the same without the precompiled header.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>
