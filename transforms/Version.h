// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The project's version: CMakeLists.txt reads it from this line for project().
#define BANDLIGHT_VERSION "0.1.0"
