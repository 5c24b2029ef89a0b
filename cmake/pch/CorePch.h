// Precompiled for the core library (core/CMakeLists.txt, ARMTRACK_CORE_PCH): Eigen and the
// standard headers nearly every one of its sources includes, directly or through the project's
// headers, parsed once per build instead of once per source. Only headers that do not depend on
// the project's own macros belong here; every source still includes what it uses, so the library
// builds the same without it.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
