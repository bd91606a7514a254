// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/ConfigJob.h"

namespace bandlight::jobs
{

ConfigResult MakeConfig(const ConfigRequest& r, Reporter& reporter, OutputSet* outputs)
{
    return BuildRequestedConfig(r, reporter, outputs);
}

}  // namespace bandlight::jobs
