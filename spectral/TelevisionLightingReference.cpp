// SPDX-License-Identifier: BSD-3-Clause
// EBU Tech 3355's tables, its CCT and its reference light (TLCI-2012 §1.1):
// everything of TLCI that is about the light alone, before the camera.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "spectral/CieData.h"
#include "spectral/Colorimetry.h"
#include "spectral/EmbeddedData.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"
#include "spectral/detail/SpectrumParsing.h"
#include "spectral/detail/TelevisionLightingDetail.h"

namespace bandlight::detail
{

namespace
{

std::vector<NamedSpectrum> ReadTable(const std::string& path)
{
    return ReadSpectraText(EmbeddedText(path), "embedded data/" + path);
}

/// Columns [first, first + N) of an embedded table, on the TLCI grid (the
/// tables are tabulated on it: checked, not resampled).
template <int N>
Eigen::Matrix<double, TLCI_SAMPLES, N> GridColumns(const std::string& path)
{
    const std::vector<NamedSpectrum> table = ReadTable(path);
    if (table.size() != size_t(N))
    {
        throw Exception("embedded data/" + path + ": expected " + std::to_string(N) +
                        " columns, found " + std::to_string(table.size()));
    }
    Eigen::Matrix<double, TLCI_SAMPLES, N> m;
    for (int c = 0; c < N; ++c)
    {
        const Spectrum& s = table[size_t(c)].spectrum;
        if (s.size() != size_t(TLCI_SAMPLES) || s.start() != TLCI_START_NM ||
            s.step() != TLCI_STEP_NM)
        {
            throw Exception("embedded data/" + path + ": not on the 380–760 nm, 5 nm grid");
        }
        for (int i = 0; i < TLCI_SAMPLES; ++i)
        {
            m(i, c) = s[size_t(i)];
        }
    }
    return m;
}

/// A locus table "cct_K,x,y" (not a spectrum: its CCTs are irregular).
std::vector<TlciLocusEntry> ReadLocus(const std::string& path)
{
    const std::string source = "embedded data/" + path;
    std::istringstream in(EmbeddedText(path));
    std::vector<TlciLocusEntry> rows;
    std::string line;
    size_t lineNo = 0;
    while (std::getline(in, line))
    {
        ++lineNo;
        if (line.empty() || line[0] == '#' || line.rfind("cct_K", 0) == 0)
        {
            continue;
        }
        std::vector<std::string> cells;
        std::istringstream cellsIn(line);
        for (std::string cell; std::getline(cellsIn, cell, ',');)
        {
            cells.push_back(cell);
        }
        if (cells.size() != 3)
        {
            Fail(source, lineNo, "expected CCT, x, y, got " + Quoted(line));
        }
        rows.push_back({ParseNumber(cells[0], source, lineNo, "a CCT"),
                        ParseNumber(cells[1], source, lineNo, "x"),
                        ParseNumber(cells[2], source, lineNo, "y")});
        if (rows.size() > 1 && !(rows.back().cctK > rows[rows.size() - 2].cctK))
        {
            Fail(source, lineNo, "CCTs must increase");
        }
    }
    return rows;
}

Eigen::Vector2d Uv(const TlciLocusEntry& e)
{
    // CIE 1960 UCS from x, y (CIE 15:2004 §8.1).
    const double den = -2.0 * e.x + 12.0 * e.y + 3.0;
    return {4.0 * e.x / den, 6.0 * e.y / den};
}

/// The nearest point of one locus to `uv` through a normal (or a bend), with
/// the squared distance; `found` stays false when there is none.
struct Candidate
{
    bool found = false;
    double distance2 = 0.0;
    TlciLocusMatch match;
};

Candidate NearestOnLocus(const std::vector<TlciLocusEntry>& table, bool daylight,
                         const Eigen::Vector2d& uv)
{
    Candidate best;
    auto offer = [&](double distance2, double cct, const Eigen::Vector2d& at,
                     const Eigen::Vector2d& direction)
    {
        if (!best.found || distance2 < best.distance2)
        {
            best.found = true;
            best.distance2 = distance2;
            best.match = {cct, at, daylight, true, direction.normalized()};
        }
    };
    double previousT = -1.0;  // where uv projects on the previous segment
    for (size_t k = 0; k + 1 < table.size(); ++k)
    {
        const Eigen::Vector2d p0 = Uv(table[k]), p1 = Uv(table[k + 1]);
        const Eigen::Vector2d seg = p1 - p0;
        // Tech 3355 eqs. [4]–[8]: the normal from uv meets the segment at p0 + t·seg.
        const double t = (uv - p0).dot(seg) / seg.squaredNorm();
        if (t >= 0.0 && t <= 1.0)
        {
            const Eigen::Vector2d foot = p0 + t * seg;
            offer((uv - foot).squaredNorm(),
                  table[k].cctK + t * (table[k + 1].cctK - table[k].cctK), foot, seg);
        }
        else if (k > 0 && previousT > 1.0 && t < 0.0)
        {
            // Beyond the end of one segment and before the start of the next:
            // the wedge outside the bend, whose nearest point is the row itself.
            offer((uv - p0).squaredNorm(), table[k].cctK, p0, seg);
        }
        previousT = t;
    }
    return best;
}

}  // namespace

const std::vector<TlciLocusEntry>& TlciPlanckianLocus()
{
    static const std::vector<TlciLocusEntry> table = ReadLocus("ref/tlci_planckian_locus.csv");
    return table;
}

const std::vector<TlciLocusEntry>& TlciDaylightLocus()
{
    static const std::vector<TlciLocusEntry> table = ReadLocus("ref/tlci_daylight_locus.csv");
    return table;
}

const Eigen::Matrix<double, TLCI_SAMPLES, 3>& TlciDaylightBasis()
{
    static const Eigen::Matrix<double, TLCI_SAMPLES, 3> m =
        GridColumns<3>("ref/tlci_daylight_basis.csv");
    return m;
}

const Eigen::Matrix<double, TLCI_SAMPLES, 3>& TlciCameraSensitivities()
{
    static const Eigen::Matrix<double, TLCI_SAMPLES, 3> m = GridColumns<3>("ref/tlci_camera.csv");
    return m;
}

const Eigen::Matrix<double, TLCI_SAMPLES, 24>& TlciChartReflectances()
{
    static const Eigen::Matrix<double, TLCI_SAMPLES, 24> m = GridColumns<24>("ref/tlci_chart.csv");
    return m;
}

const std::vector<std::string>& TlciChartNames()
{
    static const std::vector<std::string> names = []
    {
        std::vector<std::string> out;
        for (const NamedSpectrum& s : ReadTable("ref/tlci_chart.csv"))
        {
            std::string n = s.name;
            std::replace(n.begin(), n.end(), '_', ' ');
            out.push_back(n);
        }
        return out;
    }();
    return names;
}

TlciLocusMatch FindTlciLocus(const Eigen::Vector2d& uv)
{
    const Candidate planck = NearestOnLocus(TlciPlanckianLocus(), false, uv);
    const Candidate day = NearestOnLocus(TlciDaylightLocus(), true, uv);
    if (planck.found || day.found)
    {
        const bool useDay = day.found && (!planck.found || day.distance2 < planck.distance2);
        return useDay ? day.match : planck.match;
    }
    // No normal reaches uv: the nearest row of either table, ends included.
    TlciLocusMatch best;
    double bestDistance2 = INFINITY;
    for (const bool daylight : {false, true})
    {
        const std::vector<TlciLocusEntry>& table =
            daylight ? TlciDaylightLocus() : TlciPlanckianLocus();
        for (size_t k = 0; k < table.size(); ++k)
        {
            const double d2 = (Uv(table[k]) - uv).squaredNorm();
            if (d2 < bestDistance2)
            {
                const size_t a = k + 1 < table.size() ? k : k - 1;
                bestDistance2 = d2;
                best = {table[k].cctK, Uv(table[k]), daylight, false,
                        (Uv(table[a + 1]) - Uv(table[a])).normalized()};
            }
        }
    }
    return best;
}

double TlciDistance(const Eigen::Vector2d& uv, const TlciLocusMatch& match)
{
    // Tech 3355 §1.1.1 normalises the distance by 0.0054 and makes it negative
    // on the green side. It tells the side by u_T < u_L, which is the side of
    // the locus wherever v falls as the CCT rises (above 1620 K on the
    // Appendix 2 table); the side itself is used here, so that the sign means
    // green at every CCT.
    const Eigen::Vector2d offset = uv - match.uv;
    const double cross = match.tangent.x() * offset.y() - match.tangent.y() * offset.x();
    double d = offset.norm() / 0.0054 * (cross < 0.0 ? -1.0 : 1.0);
    const double t = match.cctK;
    if (t >= 4000.0 && t < 5000.0)
    {
        // Tech 3355 eqs. [16]–[17]: the loci part between 4000 and 5000 K.
        d += d > 0.0 ? 0.9 * (5000.0 - t) / 1000.0 : -0.9 * (t - 4000.0) / 1000.0;
    }
    return d;
}

TlciSamples TlciPlanckian(double cctK)
{
    constexpr double c2 = 1.435e7;  // nm·K, Tech 3355 eq. [9]
    TlciSamples s;
    for (int i = 0; i < TLCI_SAMPLES; ++i)
    {
        const double l = TLCI_START_NM + TLCI_STEP_NM * i;
        s[i] = 100.0 * std::pow(560.0 / l, 5.0) * std::expm1(c2 / (560.0 * cctK)) /
               std::expm1(c2 / (l * cctK));
    }
    return s;
}

TlciSamples TlciDaylight(double cctK)
{
    const Eigen::Vector2d xy = DaylightChromaticity(cctK);
    const double x = xy.x(), y = xy.y();
    // Tech 3355 eqs. [12]–[14]: its coefficients, close to CIE 15's but its own.
    const double m = 0.02387 + 0.25539 * x - 0.73217 * y;
    const double m1 = (-1.34674 - 1.77861 * x + 5.90757 * y) / m;
    const double m2 = (0.03638 - 31.44464 * x + 30.06400 * y) / m;
    const Eigen::Matrix<double, TLCI_SAMPLES, 3>& b = TlciDaylightBasis();
    return b.col(0) + m1 * b.col(1) + m2 * b.col(2);
}

TlciReference TlciReferenceLight(const TlciLocusMatch& match)
{
    const double t = match.cctK;
    const std::string kelvin = std::to_string(std::lround(t)) + " K";
    if (t < 3400.0)
    {
        return {TlciPlanckian(t), "Planckian " + kelvin + " (EBU Tech 3355 eq. 9)"};
    }
    if (match.daylight)
    {
        return {TlciDaylight(t), "daylight " + kelvin + " (EBU Tech 3355 Appendix 3)"};
    }
    // §1.1.2.3: between 3400 K and 5000 K a blend of two fixed lights, both
    // 100 at 560 nm, in proportion to the CCT.
    const double w = (t - 3400.0) / (5000.0 - 3400.0);
    const long percent = std::lround(100.0 * w);
    return {(1.0 - w) * TlciPlanckian(3400.0) + w * TlciDaylight(5000.0),
            "blend for " + kelvin + ": " + std::to_string(100 - percent) +
                " % Planckian 3400 K + " + std::to_string(percent) +
                " % daylight 5000 K (EBU Tech 3355 §1.1.2.3)"};
}

TlciSamples TlciGridLight(const Spectrum& light, std::vector<std::string>& warnings)
{
    const std::vector<double>& v = light.values();
    if (v.empty() || !std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); }))
    {
        throw Exception(
            "TLCI/TLMF: the light's spectrum is empty or has a value that is not finite");
    }
    const double lastNm = TLCI_START_NM + TLCI_STEP_NM * (TLCI_SAMPLES - 1);
    if (light.start() > TLCI_START_NM + 1e-9 || light.end() < lastNm - 1e-9)
    {
        warnings.push_back("the light's data cover " + Nm(light.start()) + "–" + Nm(light.end()) +
                           " nm, not all of 380–760 nm (EBU Tech 3355 §1.2): zero was assumed "
                           "outside them");
    }
    if (light.step() > TLCI_STEP_NM + 1e-9)
    {
        warnings.push_back("the light is sampled every " + Nm(light.step()) +
                           " nm, coarser than EBU Tech 3355's 5 nm: it was interpolated, and "
                           "narrow lines between its samples are lost");
    }
    TlciSamples out;
    const double offset = (light.start() - TLCI_START_NM) / TLCI_STEP_NM;
    if (std::abs(light.step() - TLCI_STEP_NM) < 1e-9 &&
        std::abs(offset - std::round(offset)) < 1e-9)
    {
        for (int i = 0; i < TLCI_SAMPLES; ++i)
        {
            const long k = long(i) - std::lround(offset);
            out[i] = k >= 0 && k < long(v.size()) ? v[size_t(k)] : 0.0;
        }
        return out;
    }
    // Any other grid: (1/5 nm) ∫ L(λ) hat_i(λ) dλ. Between consecutive
    // breakpoints (the light's samples, its ends and the hat's corners) both
    // factors are linear, so Simpson's rule is exact.
    const double h = TLCI_STEP_NM;
    for (int i = 0; i < TLCI_SAMPLES; ++i)
    {
        const double c = TLCI_START_NM + h * i;
        std::vector<double> knots = {c - h, c, c + h};
        for (double e : {light.start(), light.end()})
        {
            if (e > c - h && e < c + h)
            {
                knots.push_back(e);
            }
        }
        const long first = std::max(0L, long(std::ceil((c - h - light.start()) / light.step())));
        const long last =
            std::min(long(v.size()) - 1, long(std::floor((c + h - light.start()) / light.step())));
        for (long k = first; k <= last; ++k)
        {
            knots.push_back(light.wavelength(size_t(k)));
        }
        std::sort(knots.begin(), knots.end());
        auto hat = [&](double l) { return std::max(0.0, 1.0 - std::abs(l - c) / h); };
        double sum = 0.0;
        for (size_t k = 0; k + 1 < knots.size(); ++k)
        {
            const double a = knots[k], b = knots[k + 1], m = 0.5 * (a + b);
            if (b - a <= 0.0 || m < light.start() || m > light.end())
            {
                continue;  // empty, or outside the data where the light is zero
            }
            sum +=
                (b - a) / 6.0 * (light(a) * hat(a) + 4.0 * light(m) * hat(m) + light(b) * hat(b));
        }
        out[i] = sum / h;
    }
    return out;
}

TlciQuality TlciQualityOf(const std::vector<double>& deltaE)
{
    double sum4 = 0.0;
    int n = 0;
    for (double e : deltaE)
    {
        if (!std::isnan(e))
        {
            sum4 += e * e * e * e;
            ++n;
        }
    }
    if (n == 0)
    {
        throw Exception(
            "TLCI/TLMF: every patch was excluded (its camera signal went negative, EBU Tech 3355 "
            "§1.5.1): no score");
    }
    TlciQuality q;
    q.deltaEa = std::pow(sum4 / n, 0.25);
    // Tech 3355 eq. [59]: 3.16 is the ΔEa that scores 50, 2.4 the steepness.
    q.qa = 100.0 / (1.0 + std::pow(q.deltaEa / 3.16, 2.4));
    return q;
}

}  // namespace bandlight::detail
