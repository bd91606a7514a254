// SPDX-License-Identifier: BSD-3-Clause
#include "farm/Reporter.h"

namespace bandlight::jobs
{

Reporter& SilentReporter()
{
    static Reporter silent;
    return silent;
}

}  // namespace bandlight::jobs
