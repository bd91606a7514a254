// SPDX-License-Identifier: BSD-3-Clause
#include "render/detail/YamlReader.h"

#include <algorithm>
#include <cmath>

#include "spectral/Exception.h"

namespace bandlight::detail
{

/// "a, b, c" for messages.
std::string List(std::initializer_list<const char*> items)
{
    std::string list;
    for (const char* a : items)
    {
        list += (list.empty() ? "" : ", ") + std::string(a);
    }
    return list;
}

bool Among(const std::string& key, std::initializer_list<const char*> items)
{
    return std::any_of(items.begin(), items.end(), [&](const char* a) { return key == a; });
}

void YamlReader::fail(const YAML::Node& n, const std::string& what) const
{
    throw Exception(SourcePosition(m_path, n.Mark().is_null() ? 0 : size_t(n.Mark().line) + 1) +
                    ": " + OneLine(what));
}

YAML::Node YamlReader::keyNode(const YAML::Node& map, const std::string& key) const
{
    for (const auto& kv : map)
    {
        if (kv.first.Scalar() == key)
        {
            return kv.first;
        }
    }
    return map;
}

void YamlReader::failKey(const YAML::Node& map, const std::string& key,
                         const std::string& what) const
{
    fail(keyNode(map, key), what);
}

std::vector<std::string> YamlReader::keys(const YAML::Node& map, const std::string& where,
                                          std::initializer_list<const char*> allowed) const
{
    if (!map.IsMap())
    {
        fail(map, where + " must be a mapping");
    }
    std::vector<std::string> seen;
    for (const auto& kv : map)
    {
        if (!kv.first.IsScalar())
        {
            fail(kv.first, "a key in " + where + " must be a name");
        }
        const std::string k = kv.first.Scalar();
        if (!Among(k, allowed))
        {
            fail(kv.first,
                 "unknown key '" + k + "' in " + where + " (allowed: " + List(allowed) + ")");
        }
        if (std::find(seen.begin(), seen.end(), k) != seen.end())
        {
            // yaml-cpp would hand out the first and drop this one.
            fail(kv.first, "key '" + k + "' appears twice in " + where);
        }
        seen.push_back(k);
    }
    return seen;
}

double YamlReader::number(const YAML::Node& n, const std::string& what) const
{
    const double v = finiteNumber(n, what);
    if (std::abs(v) > kMaxMagnitude)
    {
        fail(n, what + " must be at most 1e12 in magnitude, got " + n.Scalar());
    }
    return v;
}

double YamlReader::finiteNumber(const YAML::Node& n, const std::string& what) const
{
    if (!n.IsScalar())
    {
        fail(n, what + " must be a number");
    }
    try
    {
        const double v = n.as<double>();
        if (!std::isfinite(v))
        {
            fail(n, what + " must be finite, got '" + n.Scalar() + "'");
        }
        return v;
    }
    catch (const YAML::Exception&)
    {
        fail(n, what + " must be a number, got '" + n.Scalar() + "'");
    }
}

double YamlReader::positive(const YAML::Node& n, const std::string& what) const
{
    const double v = number(n, what);
    if (!(v > 0.0))
    {
        fail(n, what + " must be positive, got " + n.Scalar());
    }
    return v;
}

double YamlReader::notNegative(const YAML::Node& n, const std::string& what) const
{
    const double v = number(n, what);
    if (v < 0.0)
    {
        fail(n, what + " must not be negative");
    }
    return v;
}

int YamlReader::pixels(const YAML::Node& n, const std::string& what) const
{
    const double v = finiteNumber(n, what);
    if (!(v >= 1.0 && v <= 16384.0) || v != std::floor(v))
    {
        fail(n, what + " must be a whole number of pixels from 1 to 16384, got " + n.Scalar());
    }
    return int(v);
}

Vec3 YamlReader::vec3(const YAML::Node& n, const std::string& what) const
{
    if (!n.IsSequence() || n.size() != 3)
    {
        fail(n, what + " must be a list of three numbers [x, y, z]");
    }
    const Vec3 v(finiteNumber(n[0], what), finiteNumber(n[1], what), finiteNumber(n[2], what));
    if (v.cwiseAbs().maxCoeff() > kMaxCoordinate)
    {
        fail(n, what + " must lie within ±1e9 (got a coordinate of " +
                    std::to_string(v.cwiseAbs().maxCoeff()) + ")");
    }
    return v;
}

std::vector<double> YamlReader::numbers(const YAML::Node& n, const std::string& what) const
{
    if (!n.IsSequence() || n.size() == 0)
    {
        fail(n, what + " must be a list of numbers");
    }
    std::vector<double> v;
    for (const auto& x : n)
    {
        v.push_back(number(x, what));
    }
    return v;
}

std::string YamlReader::text(const YAML::Node& n) const
{
    if (!n.IsScalar())
    {
        fail(n, "expected a single value (a name or a number) here, not a list or mapping");
    }
    return n.Scalar();
}

std::string YamlReader::file(const YAML::Node& n) const
{
    const std::string f = text(n);
    return !f.empty() && f[0] == '/' ? f : m_dir + f;
}

std::vector<NamedSpectrum> YamlReader::readFile(const YAML::Node& n) const
{
    try
    {
        return ReadSpectraFile(file(n));
    }
    catch (const Exception& e)
    {
        fail(n, e.what());
    }
}

}  // namespace bandlight::detail
