// SPDX-License-Identifier: BSD-3-Clause
#include "transforms/BandSet.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "spectral/Exception.h"

namespace bandlight
{

namespace
{
std::string Num(double v)
{
    std::ostringstream s;
    s << v;
    return s.str();
}

std::vector<std::string> DefaultNames(size_t n)
{
    if (n == 3)
    {
        return {"VB", "VG", "VR"};
    }
    std::vector<std::string> names;
    for (size_t i = 0; i < n; ++i)
    {
        names.push_back("B" + std::to_string(i + 1));
    }
    return names;
}
}  // namespace

BandSet::BandSet(std::vector<Band> bands) : m_bands(std::move(bands))
{
    if (m_bands.empty())
    {
        throw Exception("band set: no bands");
    }
    for (size_t i = 0; i < m_bands.size(); ++i)
    {
        const Band& b = m_bands[i];
        if (!std::isfinite(b.minNm) || !std::isfinite(b.maxNm) || !(b.maxNm > b.minNm))
        {
            throw Exception("band set: band " + b.name + " [" + Num(b.minNm) + ", " + Num(b.maxNm) +
                            ") nm is empty or not increasing");
        }
        if (i > 0 && b.minNm < m_bands[i - 1].maxNm)
        {
            throw Exception("band set: band " + b.name + " starting at " + Num(b.minNm) +
                            " nm overlaps " + m_bands[i - 1].name + " ending at " +
                            Num(m_bands[i - 1].maxNm) + " nm");
        }
    }
}

BandSet BandSet::Lecture()
{
    return FromEdges({400.0, 500.0, 600.0, 700.0});
}

BandSet BandSet::Equal(size_t n, double minNm, double maxNm)
{
    if (n == 0)
    {
        throw Exception("band set: need at least one band");
    }
    std::vector<double> edges(n + 1);
    for (size_t i = 0; i <= n; ++i)
    {
        edges[i] = minNm + (maxNm - minNm) * double(i) / double(n);
    }
    return FromEdges(edges);
}

BandSet BandSet::FromEdges(const std::vector<double>& edges)
{
    if (edges.size() < 2)
    {
        throw Exception("band set: need at least two edges, got " + std::to_string(edges.size()));
    }
    const std::vector<std::string> names = DefaultNames(edges.size() - 1);
    std::vector<Band> bands;
    for (size_t i = 0; i + 1 < edges.size(); ++i)
    {
        bands.push_back({names[i], edges[i], edges[i + 1]});
    }
    return BandSet(std::move(bands));
}

BandSet BandSet::Parse(const std::string& text)
{
    std::vector<double> edges;
    std::stringstream in(text);
    std::string token;
    while (std::getline(in, token, ','))
    {
        char* end = nullptr;
        const double v = std::strtod(token.c_str(), &end);
        if (token.empty() || *end != '\0' || !std::isfinite(v))
        {
            throw Exception("band edges '" + text + "': '" + token + "' is not a wavelength in nm");
        }
        edges.push_back(v);
    }
    return FromEdges(edges);
}

void BandSet::validateRange(double minNm, double maxNm, const std::string& what) const
{
    for (const Band& b : m_bands)
    {
        if (b.minNm < minNm - 1e-9 || b.maxNm > maxNm + 1e-9)
        {
            throw Exception("band " + b.name + " [" + Num(b.minNm) + ", " + Num(b.maxNm) +
                            ") nm lies outside the " + Num(minNm) + "–" + Num(maxNm) +
                            " nm covered by " + what);
        }
    }
}

std::string BandSet::describe() const
{
    std::string s;
    for (size_t i = 0; i < m_bands.size(); ++i)
    {
        if (i == 0 || m_bands[i].minNm != m_bands[i - 1].maxNm)
        {
            s += (s.empty() ? "" : ",") + Num(m_bands[i].minNm);
        }
        s += "," + Num(m_bands[i].maxNm);
    }
    return s;
}

}  // namespace bandlight
