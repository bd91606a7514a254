// SPDX-License-Identifier: BSD-3-Clause
#include "spectral/CameraFile.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "spectral/Colorimetry.h"
#include "spectral/Exception.h"
#include "spectral/SpectrumIO.h"
#include "spectral/TextFile.h"

namespace bandlight
{

namespace
{

std::string Num(double v)
{
    std::ostringstream o;
    o.precision(6);
    o << v;
    return o.str();
}

/// 1-based line of byte offset `pos` in `text`.
size_t LineOf(const std::string& text, size_t pos)
{
    pos = std::min(pos, text.size());
    return size_t(1) + size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(pos), '\n'));
}

void CheckChannel(const Spectrum& s, const std::string& what, const std::string& source)
{
    double peak = 0.0;
    for (double v : s.values())
    {
        peak = std::max(peak, v);
    }
    bool visible = false;
    for (size_t i = 0; i < s.size(); ++i)
    {
        const double l = s.wavelength(i);
        if (l >= 380.0 && l <= 780.0 && s[i] > 0.0)
        {
            visible = true;
        }
        if (s[i] < -0.01 * peak)
        {
            throw Exception(source + ": the " + what + " channel responds " + Num(s[i]) + " at " +
                            std::to_string(int(std::lround(l))) +
                            " nm: a sensitivity is not negative beyond noise (1 % of its peak)");
        }
    }
    if (!visible)
    {
        throw Exception(source + ": the " + what +
                        " channel has no response over 380-780 nm: not a camera sensitivity");
    }
}

CameraSensitivities Finish(CameraSensitivities cam, const std::string& source)
{
    CheckChannel(cam.red, "red", source);
    CheckChannel(cam.green, "green", source);
    CheckChannel(cam.blue, "blue", source);
    return cam;
}

using Json = nlohmann::json;

/// Throws when an object of the document names a key twice: JSON parsers
/// keep the last value, so a camera file's repeated wavelength would
/// silently replace the first.
class RepeatedKeys
{
public:
    explicit RepeatedKeys(std::string source) : m_source(std::move(source)) {}

    bool operator()(int, Json::parse_event_t event, Json& parsed)
    {
        switch (event)
        {
            case Json::parse_event_t::object_start:
                m_keys.emplace_back();
                break;
            case Json::parse_event_t::object_end:
                m_keys.pop_back();
                break;
            case Json::parse_event_t::key:
                if (!m_keys.empty() && !m_keys.back().insert(parsed.get<std::string>()).second)
                {
                    throw Exception(m_source + ": the key \"" +
                                    OneLine(parsed.get<std::string>(), 60) +
                                    "\" appears twice in one object (a wavelength given twice?): "
                                    "each wavelength once");
                }
                break;
            default:
                break;
        }
        return true;
    }

private:
    std::string m_source;
    std::vector<std::set<std::string>> m_keys;
};

Json ParseJson(const std::string& text, const std::string& source)
{
    try
    {
        return Json::parse(text, RepeatedKeys(source));
    }
    catch (const Json::parse_error& e)
    {
        throw Exception(source + ":" + std::to_string(LineOf(text, e.byte == 0 ? 0 : e.byte - 1)) +
                        ": not valid JSON: " + OneLine(e.what(), 200));
    }
    catch (const Json::exception& e)
    {
        // A number beyond double's range ("1e400") is out_of_range, not a parse error.
        throw Exception(source + ": not a camera file: " + OneLine(e.what(), 200));
    }
}

/// parent[key], which a rawtoaces camera file must have; `path` names it
/// from the root for the message.
const Json& Need(const Json& parent, const char* key, const std::string& path,
                 const std::string& source)
{
    if (!parent.is_object() || !parent.contains(key))
    {
        throw Exception(source + ": no \"" + path +
                        "\" in this camera file (rawtoaces JSON: "
                        "spectral_data.data.main maps wavelengths to [R, G, B])");
    }
    return parent.at(key);
}

/// spectral_data.data.main: two to MAX_SPECTRUM_SAMPLES wavelengths.
const Json& MainTable(const Json& spectralData, const std::string& source)
{
    const Json& main = Need(Need(spectralData, "data", "spectral_data.data", source), "main",
                            "spectral_data.data.main", source);
    if (!main.is_object() || main.size() < 2)
    {
        throw Exception(source +
                        ": spectral_data.data.main must map at least two wavelengths to "
                        "[R, G, B]");
    }
    if (main.size() > MAX_SPECTRUM_SAMPLES)
    {
        throw Exception(source + ": " + std::to_string(main.size()) + " wavelengths; at most " +
                        std::to_string(MAX_SPECTRUM_SAMPLES) + " are read");
    }
    return main;
}

/// 0, 1, 2 for a name of R, G or B ("r", "Red", …); -1 for anything else.
int ChannelIndex(const Json& name)
{
    static const std::pair<const char*, int> kNames[] = {
        {"r", 0}, {"red", 0}, {"g", 1}, {"green", 1}, {"b", 2}, {"blue", 2},
    };
    const std::string n = name.is_string() ? ToLower(name.get<std::string>()) : std::string();
    for (const auto& [known, index] : kNames)
    {
        if (n == known)
        {
            return index;
        }
    }
    return -1;
}

/// Which of R, G, B each of a row's three numbers is, from
/// spectral_data.index.main (R, G, B when the file does not say).
std::array<int, 3> ChannelOrder(const Json& spectralData, const std::string& source)
{
    std::array<int, 3> order = {0, 1, 2};
    if (!spectralData.contains("index") || !spectralData.at("index").is_object() ||
        !spectralData.at("index").contains("main"))
    {
        return order;
    }
    const Json& idx = spectralData.at("index").at("main");
    if (!idx.is_array() || idx.size() != 3)
    {
        throw Exception(source +
                        ": spectral_data.index.main must name three channels, R, G "
                        "and B");
    }
    bool seen[3] = {false, false, false};
    for (size_t k = 0; k < 3; ++k)
    {
        const int c = ChannelIndex(idx.at(k));
        if (c < 0 || seen[c])
        {
            throw Exception(source +
                            ": spectral_data.index.main must name R, G and B once "
                            "each, got " +
                            OneLine(idx.dump(), 200));
        }
        seen[c] = true;
        order[k] = c;
    }
    return order;
}

using SensitivityRow = std::pair<double, Vec3>;  ///< nm, R G B

[[noreturn]] void BadRow(const std::string& source, const std::string& key, const std::string& why)
{
    throw Exception(source + ": spectral_data.data.main \"" + OneLine(key, 60) + "\": " + why);
}

/// One "wavelength": [three numbers] entry, its numbers put in R, G, B order.
SensitivityRow ReadRow(const std::string& key, const Json& v, const std::array<int, 3>& order,
                       const std::string& source)
{
    char* end = nullptr;
    const double wl = std::strtod(key.c_str(), &end);
    if (key.empty() || end != key.c_str() + key.size() || !std::isfinite(wl) || wl <= 0.0 ||
        wl > 1e5)
    {
        BadRow(source, key, "not a wavelength in nm (0-100000)");
    }
    if (!v.is_array() || v.size() != 3)
    {
        BadRow(source, key, "needs three numbers [R, G, B]");
    }
    Vec3 rgb;
    for (size_t k = 0; k < 3; ++k)
    {
        const Json& x = v.at(k);
        if (!x.is_number() || !std::isfinite(x.get<double>()))
        {
            BadRow(source, key, "value " + OneLine(x.dump(), 60) + " is not a finite number");
        }
        rgb[order[k]] = x.get<double>();
    }
    return {wl, rgb};
}

/// The rows sorted by wavelength, and their step in nm: camera files are
/// sampled on a regular grid.
double SortOnRegularGrid(std::vector<SensitivityRow>& rows, const std::string& source)
{
    std::sort(rows.begin(), rows.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    const double step = rows[1].first - rows[0].first;
    for (size_t i = 1; i < rows.size(); ++i)
    {
        const double d = rows[i].first - rows[i - 1].first;
        if (d == 0.0)
        {
            throw Exception(source + ": the wavelength " + Num(rows[i].first) +
                            " nm is given twice: each wavelength once");
        }
        if (!(d > 0.0) || std::fabs(d - step) > 1e-6 * std::max(1.0, step))
        {
            throw Exception(source + ": wavelengths " + Num(rows[i - 1].first) + " and " +
                            Num(rows[i].first) + " break the regular grid (step " + Num(step) +
                            " nm): camera files must be sampled on a regular grid");
        }
    }
    return step;
}

/// "manufacturer model" from the header, or else the file's name.
std::string CameraName(const Json& j, const std::string& source)
{
    std::string name;
    if (j.contains("header") && j.at("header").is_object())
    {
        for (const char* k : {"manufacturer", "model"})
        {
            if (j.at("header").contains(k) && j.at("header").at(k).is_string())
            {
                name += (name.empty() ? "" : " ") + j.at("header").at(k).get<std::string>();
            }
        }
    }
    return name.empty() ? source : OneLine(name, 120);
}

/// A rawtoaces camera file: spectral_data.data.main maps each wavelength
/// (nm) to [R, G, B].
CameraSensitivities ReadJson(const std::string& text, const std::string& source)
{
    const Json j = ParseJson(text, source);
    const Json& sd = Need(j, "spectral_data", "spectral_data", source);
    const Json& main = MainTable(sd, source);
    const std::array<int, 3> order = ChannelOrder(sd, source);
    std::vector<SensitivityRow> rows;
    for (auto it = main.begin(); it != main.end(); ++it)
    {
        rows.push_back(ReadRow(it.key(), it.value(), order, source));
    }
    const double step = SortOnRegularGrid(rows, source);
    std::vector<double> ch[3];
    for (const auto& r : rows)
    {
        for (int c = 0; c < 3; ++c)
        {
            ch[c].push_back(r.second[c]);
        }
    }
    CameraSensitivities cam;
    cam.red = Spectrum(rows.front().first, step, ch[0]);
    cam.green = Spectrum(rows.front().first, step, ch[1]);
    cam.blue = Spectrum(rows.front().first, step, ch[2]);
    cam.name = CameraName(j, source);
    cam.source = source;
    return Finish(std::move(cam), source);
}

}  // namespace

CameraSensitivities ReadCameraText(const std::string& text, const std::string& source)
{
    const size_t first = text.find_first_not_of(" \t\r\n\xef\xbb\xbf");
    if (first != std::string::npos && text[first] == '{')
    {
        return ReadJson(text, source);
    }
    const std::vector<NamedSpectrum> spectra = ReadSpectraText(text, source);
    if (spectra.size() != 3)
    {
        throw Exception(source + ": a camera file holds three spectra (R, G, B), this one has " +
                        std::to_string(spectra.size()));
    }
    int index[3] = {-1, -1, -1};
    for (int k = 0; k < 3; ++k)
    {
        const std::string n = ToLower(spectra[size_t(k)].name);
        const int c = n == "r" || n == "red"     ? 0
                      : n == "g" || n == "green" ? 1
                      : n == "b" || n == "blue"  ? 2
                                                 : -1;
        if (c >= 0 && index[c] < 0)
        {
            index[c] = k;
        }
    }
    if (index[0] < 0 || index[1] < 0 || index[2] < 0)
    {
        index[0] = 0;  // not named R, G, B: taken in file order
        index[1] = 1;
        index[2] = 2;
    }
    CameraSensitivities cam;
    cam.name = source;
    cam.source = source;
    cam.red = spectra[size_t(index[0])].spectrum;
    cam.green = spectra[size_t(index[1])].spectrum;
    cam.blue = spectra[size_t(index[2])].spectrum;
    return Finish(std::move(cam), source);
}

CameraSensitivities ReadCameraFile(const std::string& path)
{
    std::string text = ReadTextFile(path, "camera file");
    CheckUtf8Text(text, path);
    return ReadCameraText(text, path);
}

CameraSensitivities ObserverCamera(Observer observer)
{
    const MatchingFunctions& cmf = GetMatchingFunctions(observer);
    CameraSensitivities cam;
    cam.name =
        observer == Observer::CIE1964_10DEG ? "CIE 1964 10° observer" : "CIE 1931 2° observer";
    cam.source = cam.name;
    cam.red = cmf.x;
    cam.green = cmf.y;
    cam.blue = cmf.z;
    return cam;
}

}  // namespace bandlight
