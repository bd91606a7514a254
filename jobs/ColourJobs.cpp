// SPDX-License-Identifier: BSD-3-Clause
#include "jobs/ColourJobs.h"

#include <nlohmann/json.hpp>

#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/Illuminants.h"

namespace bandlight::jobs
{

namespace
{
nlohmann::ordered_json RowsJson(const Eigen::MatrixXd& m, const char* names[3])
{
    nlohmann::ordered_json j;
    for (int k = 0; k < 3; ++k)
    {
        std::vector<double> row(size_t(m.cols()));
        for (Eigen::Index b = 0; b < m.cols(); ++b)
        {
            row[size_t(b)] = m(k, b);
        }
        j[names[k]] = row;
    }
    return j;
}

const char* ObserverKey(Observer observer)
{
    return observer == Observer::CIE1931_2DEG ? "1931" : "1964";
}
}  // namespace

TablesResult MakeTables(const TablesRequest& request)
{
    TablesResult r;
    r.bands = BandSet::Parse(request.bands);
    r.observer = ParseObserver(request.observer);
    r.rule = ParseBandRule(request.rule);
    r.xyz = MatchingBandMatrix(r.bands, MatchingSet::XYZ, r.observer, r.rule);
    r.rgb = MatchingBandMatrix(r.bands, MatchingSet::EBU_RGB, r.observer, r.rule);
    for (const std::string& name : StandardIlluminantNames())
    {
        r.illuminants.emplace_back(name, IlluminantBands(BuiltinIlluminant(name), r.bands, r.rule));
    }
    for (const NamedSpectrum& s : TestColourSamples())
    {
        r.remittances.emplace_back(s.name, RemittanceBands(s.spectrum, r.bands, r.rule));
    }
    return r;
}

std::string TablesDocument(const TablesResult& r)
{
    const char* xyzNames[3] = {"x", "y", "z"};
    const char* rgbNames[3] = {"r", "g", "b"};
    nlohmann::ordered_json j;
    j["bands"] = nlohmann::ordered_json::array();
    for (const Band& b : r.bands)
    {
        j["bands"].push_back({{"name", b.name}, {"min_nm", b.minNm}, {"max_nm", b.maxNm}});
    }
    const std::string key = r.observer == Observer::CIE1931_2DEG ? "cie1931_xyz" : "cie1964_xyz";
    j["observer"] = ObserverKey(r.observer);
    j["rule"] = r.rule == BandRule::SAMPLE_MEAN ? "lecture" : "exact";
    j["matching_functions"][key] = RowsJson(r.xyz, xyzNames);
    j["matching_functions"]["ebu_rgb"] = RowsJson(r.rgb, rgbNames);
    j["condition_number"] = {{key, ConditionNumber(r.xyz)},
                             {"ebu_rgb", ConditionNumber(r.rgb)},
                             {"limit", MAX_BAND_CONDITION}};
    j["illuminants"] = nlohmann::ordered_json::object();
    for (const auto& [name, v] : r.illuminants)
    {
        j["illuminants"][name] = v;
    }
    j["remittances"] = nlohmann::ordered_json::object();
    for (const auto& [name, v] : r.remittances)
    {
        j["remittances"][name] = v;
    }
    return j.dump(2);
}

XyzResult MakeXyz(const XyzRequest& request)
{
    XyzResult r;
    r.illuminant = request.illuminant.name;
    r.observer = ParseObserver(request.observer);
    r.white = IlluminantWhiteXyz(request.illuminant.spectrum, r.observer);
    std::vector<std::pair<std::string, Vec3>> values;
    if (request.reflectances.empty())
    {
        values.emplace_back(r.illuminant, r.white);
    }
    else
    {
        const XyzIntegrator integrate(request.illuminant.spectrum, r.observer);
        for (const NamedSpectrum& s : request.reflectances)
        {
            values.emplace_back(s.name, integrate(s.spectrum));
        }
    }
    for (const auto& [id, xyz] : values)
    {
        const Vec3 lab = XyzToLab(xyz, r.white);
        for (int c = 0; c < 3; ++c)
        {
            RequireFinite(xyz[c], "XYZ of '" + OneLine(id, 80) + "'");
            RequireFinite(lab[c], "L*a*b* of '" + OneLine(id, 80) + "'");
        }
        r.samples.push_back({id, xyz, XyzToxyY(xyz), lab});
    }
    return r;
}

std::string XyzDocument(const XyzResult& r)
{
    nlohmann::ordered_json j;
    j["illuminant"] = r.illuminant;
    j["observer"] = ObserverKey(r.observer);
    j["white_XYZ"] = {r.white.x(), r.white.y(), r.white.z()};
    j["samples"] = nlohmann::ordered_json::array();
    for (const XyzSample& s : r.samples)
    {
        j["samples"].push_back({{"id", s.id},
                                {"XYZ", {s.xyz.x(), s.xyz.y(), s.xyz.z()}},
                                {"xy", {s.xyY.x(), s.xyY.y()}},
                                {"Lab", {s.lab.x(), s.lab.y(), s.lab.z()}}});
    }
    return j.dump(2);
}

CriResult MakeCri(const Light& illuminant)
{
    CriResult r{illuminant.name, ComputeColourRendering(illuminant.spectrum)};
    const ColourRendering& cr = r.rendering;
    RequireFinite(cr.cctK, "CCT");
    RequireFinite(cr.duv, "Duv");
    RequireFinite(cr.ra, "Ra");
    for (size_t i = 0; i < cr.r.size(); ++i)
    {
        RequireFinite(cr.r[i], "R" + std::to_string(i + 1));
    }
    return r;
}

std::string CriDocument(const CriResult& r)
{
    const ColourRendering& cr = r.rendering;
    nlohmann::ordered_json j;
    j["illuminant"] = r.illuminant;
    j["cct_K"] = cr.cctK;
    j["duv"] = cr.duv;
    j["Ra"] = cr.ra;
    j["R"] = cr.r;
    j["outside_duv_tolerance"] = cr.outsideTolerance;
    return j.dump(2);
}

}  // namespace bandlight::jobs
