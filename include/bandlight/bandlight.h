// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// bandlight's public header, as a host includes it: <bandlight/bandlight.h>
// (find_package(bandlight), target bandlight::jobs). It brings every job's
// request, result and entry point (the library the command and the Python
// module are faces of), and the OCIO transforms a host builds looks from.
// The headers it names are installed beside it under include/bandlight/;
// in the source tree they are included from the repository's root.

#include "jobs/AccuracyJob.h"
#include "jobs/ApplyJob.h"
#include "jobs/ColourJobs.h"
#include "jobs/ConfigJob.h"
#include "jobs/IdtJob.h"
#include "jobs/LutJob.h"
#include "jobs/MethodsJob.h"
#include "jobs/PackageJob.h"
#include "jobs/PlotJob.h"
#include "jobs/RenderJob.h"
#include "jobs/SpectralJob.h"
#include "jobs/WallJob.h"
#include "plugin/OcioTransforms.h"
#include "spectral/Illuminants.h"
