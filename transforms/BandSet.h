// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <string>
#include <vector>

namespace bandlight
{

/// One wavelength band [minNm, maxNm).
struct Band
{
    std::string name;
    double minNm = 0.0;
    double maxNm = 0.0;

    double width() const noexcept { return maxNm - minNm; }
};

/// An ordered set of adjacent or disjoint bands, validated on construction:
/// edges increasing, every band of positive width, bands not overlapping.
class BandSet
{
public:
    /// Throws Exception when the bands are empty, not increasing or overlap.
    explicit BandSet(std::vector<Band> bands);

    /// The band model's three bands: VB [400, 500), VG [500, 600), VR [600, 700).
    static BandSet Lecture();

    /// n equal bands over [minNm, maxNm), named B1..Bn (or VB/VG/VR for the
    /// lecture's range with n = 3).
    static BandSet Equal(size_t n, double minNm, double maxNm);

    /// Adjacent bands from edges e0 < e1 < ... < en; names B1..Bn (VB/VG/VR
    /// for three bands). Throws Exception for fewer than two edges or edges
    /// that do not increase.
    static BandSet FromEdges(const std::vector<double>& edges);

    /// Parses "E0,E1,...,En" (nm) into FromEdges; throws with the bad token.
    static BandSet Parse(const std::string& text);

    /// Throws Exception when a band reaches outside [minNm, maxNm], the
    /// range the data in use cover; `what` names that data in the message.
    void validateRange(double minNm, double maxNm, const std::string& what) const;

    size_t size() const noexcept { return m_bands.size(); }
    const Band& operator[](size_t i) const noexcept { return m_bands[i]; }
    const std::vector<Band>& bands() const noexcept { return m_bands; }
    std::vector<Band>::const_iterator begin() const noexcept { return m_bands.begin(); }
    std::vector<Band>::const_iterator end() const noexcept { return m_bands.end(); }

    /// "400,500,600,700"-style description for messages and file names.
    std::string describe() const;

private:
    std::vector<Band> m_bands;
};

}  // namespace bandlight
