// SPDX-License-Identifier: BSD-3-Clause
#include "report/DeltaEMap.h"

#include <algorithm>
#include <cassert>
#include <sstream>

#include "imageio/ImageFiles.h"
#include "report/Gnuplot.h"
#include "spectral/Statistics.h"
#include "transforms/Accuracy.h"

namespace bandlight
{

DeltaEMap::DeltaEMap(int width, int height)
    : m_width(width),
      m_height(height),
      m_values(size_t(width) * size_t(height), 0.0f),
      m_mask(size_t(width) * size_t(height), 0)
{
}

void DeltaEMap::set(size_t index, double deltaE)
{
    assert(index < m_values.size());
    m_values[index] = float(deltaE);
    m_mask[index] = 1;
    m_measured.push_back(deltaE);
}

DeltaESummary DeltaEMap::summary() const
{
    const Statistics all = Summarise(m_measured);
    DeltaESummary s;
    s.pixels = all.count;
    s.mean = all.mean;
    s.p95 = all.p95;
    s.max = all.max;
    return s;
}

void WriteDeltaEMap(const DeltaEMap& map, const std::string& exr, const std::string& png,
                    const std::string& title,
                    const std::vector<std::pair<std::string, std::string>>& attributes,
                    OutputSet& outputs)
{
    ImageDescription data;
    data.colorSpace = "data";
    data.attributes = attributes;
    WriteImage(exr, map.values().data(), map.width(), map.height(), 1, {"dE00"}, data,
               PixelType::FLOAT, &outputs);
    // The colour map: block means of the measured pixels on at most 400
    // columns; a block with none is no data (NaN: not drawn, so the slate
    // background shows, never the colour of a perfect pixel).
    const size_t width = size_t(map.width());
    const size_t height = size_t(map.height());
    const std::vector<float>& values = map.values();
    const std::vector<char>& measured = map.measured();
    const size_t block = std::max<size_t>(1, (width + 399) / 400);
    std::ostringstream matrix;
    for (size_t by = 0; by < height; by += block)
    {
        for (size_t bx = 0; bx < width; bx += block)
        {
            double s = 0.0;
            int k = 0;
            for (size_t y = by; y < std::min(by + block, height); ++y)
            {
                for (size_t x = bx; x < std::min(bx + block, width); ++x)
                {
                    if (measured[y * width + x])
                    {
                        s += values[y * width + x];
                        ++k;
                    }
                }
            }
            matrix << (bx ? " " : "");
            if (k > 0)
            {
                matrix << s / k;
            }
            else
            {
                matrix << "NaN";
            }
        }
        matrix << "\n";
    }
    // A perceptually ordered palette (matplotlib's magma) from black to
    // near-white, so the map reads in grey too.
    std::ostringstream script;
    script << "set title " << GnuplotQuote(title) << " font ',10'\n"
           << "set size ratio -1\nunset key\nunset xtics\nunset ytics\n"
              "set yrange [*:*] reverse\nset cbrange [0:"
           << kDeltaEMapTop << "]\n"
           << "set cblabel 'CIEDE2000 (" << kDeltaEMapTop << " and above: white; slate: no data)'\n"
           << "set object 1 rectangle from graph 0, graph 0 to graph 1, graph 1 behind "
              "fillcolor rgb '#5b7083' fillstyle solid noborder\n"
           << "set palette defined (0 '#000004', 2 '#3b0f70', 4 '#8c2981', 6 '#de4968', "
              "8 '#fe9f6d', 10 '#fcfdbf')\n"
              "plot $bandlight_data matrix with image\n";
    RunGnuplot(script.str(), matrix.str(), png, &outputs);
}

}  // namespace bandlight
