// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// The stages of EBU Tech 3355 (TLCI-2012, TLMF-2013) that
// spectral/TelevisionLighting.cpp puts together, exposed so that the tests
// check each against its published figure. Not installed.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "spectral/Spectrum.h"

namespace bandlight::detail
{

/// Tech 3355 §1.2 does all its mathematics on one grid: 380–760 nm at 5 nm.
constexpr double TLCI_START_NM = 380.0;
constexpr double TLCI_STEP_NM = 5.0;
constexpr int TLCI_SAMPLES = 77;
static_assert(TLCI_START_NM + TLCI_STEP_NM * (TLCI_SAMPLES - 1) == 760.0,
              "Tech 3355's grid ends at 760 nm");

/// A spectrum on Tech 3355's grid: sample i is at 380 + 5 i nm.
using TlciSamples = Eigen::Matrix<double, TLCI_SAMPLES, 1>;

/// One row of a Tech 3355 Appendix 2 locus table.
struct TlciLocusEntry
{
    double cctK;
    double x, y;  ///< CIE 1931 chromaticity
};

/// Tech 3355 Appendix 2: the Planckian locus (1000–5000 K, 152 rows) and the
/// daylight locus (5000–25000 K, 104 rows), as tabulated.
const std::vector<TlciLocusEntry>& TlciPlanckianLocus();
const std::vector<TlciLocusEntry>& TlciDaylightLocus();

/// Tech 3355 Appendix 3 daylight vectors S0, S1, S2 and Appendix 5 camera
/// sensitivities r̄, ḡ, b̄ (columns), on the TLCI grid.
const Eigen::Matrix<double, TLCI_SAMPLES, 3>& TlciDaylightBasis();
const Eigen::Matrix<double, TLCI_SAMPLES, 3>& TlciCameraSensitivities();

/// Tech 3355 Appendix 4: the 24 chart reflectances (columns, chart order)
/// and the patches' names.
const Eigen::Matrix<double, TLCI_SAMPLES, 24>& TlciChartReflectances();
const std::vector<std::string>& TlciChartNames();

/// Where a chromaticity meets Tech 3355's loci (§1.1.1).
struct TlciLocusMatch
{
    double cctK = 0.0;
    Eigen::Vector2d uv{0.0, 0.0};  ///< the point of the locus, CIE 1960 (u, v)
    bool daylight = false;         ///< on the daylight locus (else the Planckian)
    /// False when no normal from either locus reaches the chromaticity: the
    /// nearest tabulated point was taken (beyond 1000 K or 25000 K).
    bool onNormal = true;
    /// Unit direction of the locus there, towards higher CCT.
    Eigen::Vector2d tangent{-1.0, 0.0};
};

/// The CCT of a CIE 1960 (u, v) chromaticity as Tech 3355 §1.1.1 finds it:
/// the foot of the shortest normal dropped onto a segment between adjacent
/// rows of either Appendix 2 table (the two loci are kept apart: they do not
/// meet), the CCT interpolated linearly along that segment. Where the
/// chromaticity sits in the wedge outside a bend of a locus, no segment's
/// normal reaches it and the row at the bend is its nearest point; a
/// table's two end rows are used only when nothing else is found.
TlciLocusMatch FindTlciLocus(const Eigen::Vector2d& uv);

/// Tech 3355's distance of `uv` from the locus point of `match`, in units of
/// 0.0054 in CIE 1960 (u, v) (CIE 13.3's limit for a reference to be
/// meaningful, so |d| = 1 is that limit), negative on the green side (above
/// the locus), positive towards magenta. Between 4000 and 5000 K it is
/// widened as Tech 3355 eqs. [16]–[17] prescribe, the Planckian and daylight
/// loci being apart there.
double TlciDistance(const Eigen::Vector2d& uv, const TlciLocusMatch& match);

/// Tech 3355 eq. [9]: Planck's law with c2 = 1.435e7 nm·K, 100 at 560 nm.
TlciSamples TlciPlanckian(double cctK);

/// Tech 3355 eqs. [10]–[14]: S0 + M1 S1 + M2 S2 from the Appendix 3 vectors,
/// with the chromaticity of CIE daylight at `cctK` (CIE 15:2004 eq. 3.3,
/// 4000–25000 K) and Tech 3355's own coefficients of M, M1, M2 (unrounded);
/// 100 at 560 nm.
TlciSamples TlciDaylight(double cctK);

/// The TLCI reference light of a locus match (Tech 3355 §1.1.2): Planckian
/// below 3400 K, daylight on the daylight locus, and from 3400 K to 5000 K
/// the blend (1 − w) P3400 + w D5000, w = (CCT − 3400) / 1600 (§1.1.2.3).
struct TlciReference
{
    TlciSamples spd;
    std::string name;
};
TlciReference TlciReferenceLight(const TlciLocusMatch& match);

/// A light brought onto the TLCI grid. On that grid already (5 nm steps on
/// multiples of 5 nm), its samples are taken as they are; on any other grid,
/// each sample is the integral of the light's linear interpolant against a
/// triangle of ±5 nm around it, divided by 5 nm, so that summing against a
/// table on the TLCI grid is the exact integral of the light against the
/// table's linear interpolant: a narrow line at 1 nm sampling keeps its power
/// wherever it falls. Zero outside the light's data. Appends a note to
/// `warnings` when the data do not cover 380–760 nm or are coarser than 5 nm.
/// Throws Exception for values that are not finite.
TlciSamples TlciGridLight(const Spectrum& light, std::vector<std::string>& warnings);

/// Qa and ΔEa of per-patch CIEDE2000 differences (Tech 3355 eqs. [58]–[59]):
/// ΔEa = (mean ΔE⁴)^(1/4) over the patches that are not NaN (excluded),
/// Qa = 100 / (1 + (ΔEa / 3.16)^2.4). Throws Exception when all are NaN.
struct TlciQuality
{
    double qa = 0.0;
    double deltaEa = 0.0;
};
TlciQuality TlciQualityOf(const std::vector<double>& deltaE);

}  // namespace bandlight::detail
