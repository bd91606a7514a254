// SPDX-License-Identifier: BSD-3-Clause
// Spectral images (jobs/SpectralJob): read, integrated and relit in memory,
// and spectral EXRs converted to RGB EXRs as `bandlight spectral` does.
#include "PyBandlight.h"
#include "requests/Defaults.h"
#include "jobs/SpectralJob.h"

namespace bandlight::python
{

namespace
{

const char* KindName(SpectralKind kind)
{
    return kind == SpectralKind::EMISSIVE ? "emissive" : "reflective";
}

jobs::SpectralOptions Options(const py::object& src, const py::object& dst,
                              const std::string& working, const std::string& plates,
                              const std::string& adaptation, const py::object& observer,
                              const py::object& channels, const std::string& kind,
                              const std::string& sampling)
{
    jobs::SpectralOptions o;
    if (!src.is_none())
    {
        o.from = ToLight(src);
    }
    if (!dst.is_none())
    {
        o.to = ToLight(dst);
    }
    o.workingSpace = working;
    o.plates.plates = plates;
    o.plates.adaptation = adaptation;
    o.plates.parsed();
    o.observer = ToObserver(observer) == Observer::CIE1964_10DEG ? "1964" : "1931";
    if (!channels.is_none())
    {
        if (py::isinstance<py::dict>(channels))
        {
            for (const auto& item : channels.cast<py::dict>())
            {
                if (!py::isinstance<py::str>(item.first))
                {
                    throw py::type_error(
                        "channels= maps channel names (str) to wavelengths in nm, got the key " +
                        OneLine(py::repr(item.first), 40) + " (" +
                        std::string(py::str(py::type::of(item.first).attr("__name__"))) + ")");
                }
                double nm = 0.0;
                try
                {
                    nm = item.second.cast<double>();
                }
                catch (const py::cast_error&)
                {
                    throw py::type_error("channels=: the wavelength of '" +
                                         OneLine(item.first.cast<std::string>(), 40) +
                                         "' must be a number of nm, got " +
                                         OneLine(py::repr(item.second), 40));
                }
                o.channelWavelengths[item.first.cast<std::string>()] = nm;
            }
        }
        else
        {
            o.channelWavelengthsFile = PathText(channels, "channels");
        }
    }
    o.kind = kind;
    o.sampling = sampling;
    return o;
}

/// (wavelengths, spectra (h, w, n) float32, kind, layout description).
py::tuple ReadSpectral(const py::object& path, const py::object& channels, const std::string& kind,
                       const std::string& sampling)
{
    jobs::SpectralOptions o =
        Options(py::none(), py::none(), defaults::WORKING_SPACE, defaults::PLATES,
                defaults::ADAPTATION, py::str(defaults::OBSERVER), channels, kind, sampling);
    const std::string file = PathText(path, "path");
    jobs::SpectralImage image = jobs::ReadSpectralImage(file, o);
    const size_t n = image.layout.wavelengths.size();
    std::vector<float> spectra = image.spectra();
    py::array_t<float> array({size_t(image.height), size_t(image.width), n});
    std::copy(spectra.begin(), spectra.end(), array.mutable_data());
    py::array_t<double> wavelengths(n);
    std::copy(image.layout.wavelengths.begin(), image.layout.wavelengths.end(),
              wavelengths.mutable_data());
    return py::make_tuple(wavelengths, array, KindName(image.layout.kind), image.layout.describe());
}

/// Spectra (..., n) on `wavelengths` → working RGB (..., 3).
py::array_t<float> SpectralToRgb(
    const py::array_t<float, py::array::c_style | py::array::forcecast>& spectra,
    const py::array_t<double, py::array::c_style | py::array::forcecast>& wavelengths,
    const std::string& kind, const py::object& src, const py::object& dst,
    const std::string& working, const std::string& plates, const std::string& adaptation,
    const py::object& observer, const std::string& sampling, int threads)
{
    if (wavelengths.ndim() != 1 || wavelengths.shape(0) < 2)
    {
        throw ParameterError("{wavelengths} must be a 1-D array of at least two wavelengths (nm)");
    }
    const size_t n = size_t(wavelengths.shape(0));
    if (spectra.ndim() < 1 || size_t(spectra.shape(spectra.ndim() - 1)) != n)
    {
        throw ParameterError("{spectra} must end in an axis of " + std::to_string(n) +
                             " samples, one per wavelength");
    }
    jobs::SpectralOptions o =
        Options(src, dst, working, plates, adaptation, observer, py::none(), kind, sampling);
    // The wavelengths as channel names of an image with these channels.
    std::vector<std::string> names;
    const SpectralKind k = kind == "reflective" ? SpectralKind::REFLECTIVE : SpectralKind::EMISSIVE;
    if (kind != "emissive" && kind != "reflective")
    {
        throw ParameterError("{kind} must be emissive or reflective, got '" + OneLine(kind, 40) +
                             "'");
    }
    for (size_t i = 0; i < n; ++i)
    {
        names.push_back(SpectralChannelName(k, wavelengths.at(i)));
    }
    SpectralLayoutOptions lo;
    lo.sampling = o.layoutOptions().sampling;
    const SpectralLayout layout = FindSpectralLayout("spectra", names, {}, lo);
    const jobs::SpectralConversion conversion = jobs::MakeSpectralConversion(layout, int(n), o);
    for (const std::string& note : conversion.notes)
    {
        Warn(note);
    }
    const size_t count = size_t(spectra.size()) / n;
    std::vector<ssize_t> shape(spectra.shape(), spectra.shape() + spectra.ndim());
    shape.back() = 3;
    py::array_t<float> rgb(shape);
    const float* in = spectra.data();
    float* out = rgb.mutable_data();
    const int t = ToThreads(threads);
    {
        py::gil_scoped_release release;
        jobs::CheckSpectralPixels(layout, "spectra", names, in, count, int(n));
        jobs::IntegrateSpectralPixels(conversion, in, count, int(n), out, t);
        jobs::CheckIntegratedPixels("spectra", out, count, 0);
    }
    return rgb;
}

py::dict Spectral(const py::object& input, const py::object& output,
                  const std::optional<std::string>& frames, const py::object& src,
                  const py::object& dst, const std::string& working,
                  const std::optional<std::string>& platesArg, const std::string& adaptation,
                  const py::object& observer, const py::object& channels, const std::string& kind,
                  const std::string& sampling, int threads, bool skipExisting, bool keepGoing,
                  const py::object& lightGroups)
{
    // Light groups show several lights, no one white: lit unless said.
    const std::string plates =
        platesArg.value_or(lightGroups.is_none() ? defaults::PLATES : defaults::LIGHT_GROUP_PLATES);
    jobs::SpectralRequest r;
    r.files.input = PathText(input, "input");
    r.files.output = PathText(output, "output");
    r.files.frames = frames.value_or("");
    r.files.skipExisting = skipExisting;
    r.files.keepGoing = keepGoing;
    r.options = Options(src, dst, working, plates, adaptation, observer, channels, kind, sampling);
    if (!lightGroups.is_none())
    {
        for (const auto& [key, value] :
             CastTo<py::dict>(lightGroups, "light_groups", "a dict {group: (src, dst)}"))
        {
            const py::tuple lights =
                CastTo<py::tuple>(value, "a light group's change", "a tuple (src, dst)");
            if (lights.size() != 2)
            {
                throw ParameterError("{light_groups} takes {group: (src, dst)}");
            }
            r.options.lightGroups.push_back({CastTo<std::string>(key, "a group's name", "str"),
                                             ToLight(lights[0]), ToLight(lights[1])});
        }
    }
    r.threads = ToThreads(threads);
    jobs::SpectralResult result;
    {
        py::gil_scoped_release release;
        result = jobs::ConvertSpectralImages(r, Warnings());
    }
    py::dict d =
        FrameRunDict(result.run.frames, result.run.skipped, result.run.failed, result.run.seconds);
    d["layout"] = result.layout;
    d["applied"] = result.applied;
    return d;
}

constexpr const char* kConventionsDoc = R"doc(
Conventions (docs/spectral.md): emissive spectra are radiance, XYZ =
Σ L·cmf·Δλ / Σ ȳ·Δλ (a spectrum of constant value 1 has Y = 1); with src
and dst each wavelength is multiplied by dst/src, dst scaled to src's
luminance so that a white reflector keeps its Y. Reflective spectra are
remittances rendered under dst, scaled so that a white reflector has Y = 1.
plates="balanced" white-balances the result from the light it shows (dst) to
the working white by adaptation; an emissive image only integrated stays as
lit. observer: "1931" or "1964". sampling: "auto", "points" or "buckets".
)doc";

}  // namespace

void AddSpectralImage(py::module_& m)
{
    m.def("read_spectral_image", &ReadSpectral, py::arg("path"), py::kw_only(),
          py::arg("channels") = py::none(), py::arg("kind") = defaults::SPECTRAL_KIND,
          py::arg("sampling") = defaults::SPECTRAL_SAMPLING, R"doc(
Reads a spectral EXR (the Fichet 2021 layout, pbrt-v4's spectral film, or
channels named otherwise) through OpenImageIO. Returns (wavelengths in nm,
a float32 array (height, width, n) of the spectra, the kind "emissive" or
"reflective", the layout described). channels: for channels named otherwise,
a dict {channel: wavelength_nm} or a CSV file of them (of kind ``kind``).
Bad files raise ValueError naming the file and the channel.
)doc");
    m.def("spectral_to_rgb", &SpectralToRgb, py::arg("spectra"), py::arg("wavelengths"),
          py::kw_only(), py::arg("kind") = defaults::SPECTRAL_KIND, py::arg("src") = py::none(),
          py::arg("dst") = py::none(), py::arg("working_space") = defaults::WORKING_SPACE,
          py::arg("plates") = defaults::PLATES, py::arg("adaptation") = defaults::ADAPTATION,
          py::arg("observer") = defaults::OBSERVER,
          py::arg("sampling") = defaults::SPECTRAL_SAMPLING, py::arg("threads") = defaults::THREADS,
          (std::string(R"doc(
Spectra (any shape ending in one axis of len(wavelengths) samples) to linear
RGB in working_space, shape (..., 3), with the GIL released: one dot product
per pixel and channel, as ``bandlight spectral`` computes it. Point samples
by default (sampling="buckets" for means over each sample's interval).
)doc") + kConventionsDoc)
              .c_str());
    m.def("spectral", &Spectral, py::arg("input"), py::arg("output"), py::kw_only(),
          py::arg("frames") = py::none(), py::arg("src") = py::none(), py::arg("dst") = py::none(),
          py::arg("working_space") = defaults::WORKING_SPACE, py::arg("plates") = py::none(),
          py::arg("adaptation") = defaults::ADAPTATION, py::arg("observer") = defaults::OBSERVER,
          py::arg("channels") = py::none(), py::arg("kind") = defaults::SPECTRAL_KIND,
          py::arg("sampling") = defaults::SPECTRAL_SAMPLING, py::arg("threads") = defaults::THREADS,
          py::arg("skip_existing") = false, py::arg("keep_going") = false,
          py::arg("light_groups") = py::none(),
          (std::string(R"doc(
Converts a spectral EXR (or a frame sequence of them, with frames=) to an
RGB EXR tagged with its colour space: the job of ``bandlight spectral``.
Returns {"layout", "applied", "frames", "skipped", "failed", "seconds"}.
plates: None is "balanced", or "lit" with light_groups. light_groups: {group:
(src, dst)}: each spectral light group of a `render(spectra=True,
light_groups=True)` EXR relit exactly from its light to its new one, the
others and the residual integrated as they are; the output holds the beauty
and each group's R, G, B (docs/lightgroups.md).
)doc") + kConventionsDoc)
              .c_str());
}

}  // namespace bandlight::python
