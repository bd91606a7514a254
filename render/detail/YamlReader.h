// SPDX-License-Identifier: BSD-3-Clause
#pragma once

// Checked reading of YAML values for the scene reader: every refusal is an
// Exception "FILE:LINE: what" at the offending node. Internal to render/
// (it includes yaml-cpp); the scene format itself is render/SceneFile.h.

#include <initializer_list>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "spectral/Colorimetry.h"
#include "spectral/SpectrumIO.h"

namespace bandlight::detail
{

/// Scene coordinates beyond this are refused: squared distances stay finite.
constexpr double kMaxCoordinate = 1e9;
/// Any number in a scene beyond this magnitude is refused: products of
/// intensities, powers and remittances over a spectrum stay far from
/// overflow (1e12 squared, times 10^4 samples, is 1e28).
constexpr double kMaxMagnitude = 1e12;

/// "a, b, c" for messages.
std::string List(std::initializer_list<const char*> items);
/// Whether `key` is one of `items`.
bool Among(const std::string& key, std::initializer_list<const char*> items);

/// Reads values from one YAML file: `path` names it in messages, `dir`
/// (ending in '/', or empty) anchors its relative file names.
class YamlReader
{
public:
    YamlReader(std::string path, std::string dir) : m_path(std::move(path)), m_dir(std::move(dir))
    {
    }

    /// Throws "PATH:LINE: what" at node `n`'s line (0 when it has none).
    [[noreturn]] void fail(const YAML::Node& n, const std::string& what) const;
    /// The key node of `key` in `map` (for its line); the map itself when absent.
    YAML::Node keyNode(const YAML::Node& map, const std::string& key) const;
    /// fail() at the line of the key `key` of `map`.
    [[noreturn]] void failKey(const YAML::Node& map, const std::string& key,
                              const std::string& what) const;
    /// The mapping's keys, in file order; a node that is not a mapping, an
    /// unknown key and a repeated key are errors (`where` names the mapping).
    std::vector<std::string> keys(const YAML::Node& map, const std::string& where,
                                  std::initializer_list<const char*> allowed) const;
    /// A number with the scene-wide magnitude limit (kMaxMagnitude).
    double number(const YAML::Node& n, const std::string& what) const;
    /// Any finite number, for values that check a narrower range themselves.
    double finiteNumber(const YAML::Node& n, const std::string& what) const;
    double positive(const YAML::Node& n, const std::string& what) const;
    double notNegative(const YAML::Node& n, const std::string& what) const;
    /// An image size: a whole number of pixels, 1 to 16384.
    int pixels(const YAML::Node& n, const std::string& what) const;
    /// [x, y, z] within ±kMaxCoordinate.
    Vec3 vec3(const YAML::Node& n, const std::string& what) const;
    /// A non-empty list of numbers.
    std::vector<double> numbers(const YAML::Node& n, const std::string& what) const;
    /// A scalar as text (a list or mapping here is an error).
    std::string text(const YAML::Node& n) const;
    /// A file name, relative to the YAML file unless absolute.
    std::string file(const YAML::Node& n) const;
    /// The spectra of the file `n` names (CSV or CGATS); its errors at `n`'s line.
    std::vector<NamedSpectrum> readFile(const YAML::Node& n) const;

private:
    std::string m_path;
    std::string m_dir;
};

}  // namespace bandlight::detail
