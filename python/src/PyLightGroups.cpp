// SPDX-License-Identifier: BSD-3-Clause
// Light groups in memory: a dict of group → array relit per group, the
// beauty rebuilt as Σ relit groups + residual (jobs/LightGroups), as
// `bandlight apply --light-group` does it to files.
#include "PyBandlight.h"
#include "requests/Defaults.h"
#include "imaging/ImageApply.h"
#include "imaging/LightGroups.h"

namespace bandlight::python
{

namespace
{
using F32 = py::array_t<float, py::array::c_style | py::array::forcecast>;

std::string Shape(const py::array& a)
{
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i)
    {
        s += (i ? ", " : "") + std::to_string(a.shape(i));
    }
    return s + (a.ndim() == 1 ? ",)" : ")");
}

/// An array of RGB pixels (last dimension 3), float32 C order.
F32 RgbArray(const py::handle& arg, const std::string& what)
{
    const F32 a = F32::ensure(arg);
    if (!a || a.ndim() < 1 || a.shape(a.ndim() - 1) != 3)
    {
        throw Exception(what +
                        " must be an array of R, G, B in its last dimension, e.g. "
                        "(height, width, 3)" +
                        (a ? ", got shape " + Shape(a) : std::string()));
    }
    return a;
}

/// The groups' layers and the beauty, checked: RGB arrays of one shape.
struct GroupImages
{
    std::vector<std::string> names;  ///< in the dict's order
    std::vector<F32> arrays;         ///< one per name
    std::optional<F32> beauty;       ///< none: the groups' sum
    std::vector<py::ssize_t> shape;  ///< every array's
    size_t count = 0;                ///< pixels
    long width = 0;  ///< the second-to-last dimension; fewer than 3 dimensions are one row
    long height = 0;

    /// Floats per pixel of the job's buffer: the beauty's R, G, B, then each
    /// group's.
    size_t channels() const { return 3 + 3 * names.size(); }
};

/// What every change of light shares: the keywords after `changes`.
struct ChangeArgs
{
    std::string method;
    std::string working;
    py::object observer;
    py::object training;
    PlatesArgs plates;
    int threads = 0;
};

/// `groups` in the dict's order and `beauty`, each an RGB array of the first
/// group's shape.
GroupImages ToGroupImages(const py::dict& groups, const py::object& beauty)
{
    if (groups.empty())
    {
        throw Exception("groups is empty: give {name: array of R, G, B}");
    }
    GroupImages images;
    std::vector<std::string>& names = images.names;
    std::vector<F32>& arrays = images.arrays;
    for (const auto& [key, value] : groups)
    {
        names.push_back(CastTo<std::string>(key, "a group's name", "str"));
        arrays.push_back(RgbArray(value, "group '" + names.back() + "'"));
        if (Shape(arrays.back()) != Shape(arrays.front()))
        {
            throw Exception("group '" + names.back() + "' has shape " + Shape(arrays.back()) +
                            ", group '" + names.front() + "' " + Shape(arrays.front()) +
                            ": every group is the same image's layer");
        }
    }
    const F32& first = arrays.front();
    images.shape.assign(first.shape(), first.shape() + first.ndim());
    images.count = size_t(first.size()) / 3;
    images.width =
        first.ndim() >= 3 ? long(images.shape[images.shape.size() - 2]) : long(images.count);
    images.height = images.width > 0 ? long(images.count) / images.width : 0;
    if (!beauty.is_none())
    {
        images.beauty = RgbArray(beauty, "beauty");
        if (Shape(*images.beauty) != Shape(first))
        {
            throw Exception("beauty has shape " + Shape(*images.beauty) + ", the groups " +
                            Shape(first));
        }
    }
    return images;
}

/// The job's buffer as light groups: the beauty in channels 0-2, group g in
/// 3 + 3g to 5 + 3g, each named as given.
jobs::LightGroupLayout BufferLayout(const std::vector<std::string>& names)
{
    jobs::LightGroupLayout layout;
    layout.beauty[0] = 0;
    layout.beauty[1] = 1;
    layout.beauty[2] = 2;
    for (size_t g = 0; g < names.size(); ++g)
    {
        jobs::LightGroupLayer l;
        l.name = names[g];
        l.layer = names[g];
        l.naming = jobs::LightGroupNaming::MAPPED;
        for (int c = 0; c < 3; ++c)
        {
            l.rgb[c] = int(3 + 3 * g) + c;
        }
        layout.groups.push_back(l);
    }
    return layout;
}

/// The works: one relighter per change; a group relit to its own light is
/// carried exactly.
std::map<std::string, jobs::LightGroupWork> ToWorks(const py::dict& changes,
                                                    const jobs::LightGroupLayout& layout,
                                                    const std::vector<std::string>& names,
                                                    const ChangeArgs& change)
{
    std::map<std::string, jobs::LightGroupWork> works;
    for (const auto& [key, value] : changes)
    {
        const std::string name = CastTo<std::string>(key, "a change's group", "str");
        if (!layout.find(name))
        {
            std::string have;
            for (const std::string& n : names)
            {
                have += (have.empty() ? "" : ", ") + n;
            }
            throw Exception("changes names the light group '" + name +
                            "', which groups does not hold (it has " + have + ")");
        }
        const py::tuple lights = CastTo<py::tuple>(value, "changes['" + name + "']",
                                                   "a tuple (src, dst) or (src, dst, method)");
        if (lights.size() != 2 && lights.size() != 3)
        {
            throw Exception("changes['" + name + "'] must be (src, dst) or (src, dst, method), "
                            "as apply(light_groups=...) takes it");
        }
        const Light from = ToLight(lights[0]);
        const Light to = ToLight(lights[1]);
        // A group's own method, as NAME=FROM:TO@METHOD on the command line.
        const std::string method =
            lights.size() == 3
                ? CastTo<std::string>(lights[2], "changes['" + name + "'][2]", "a method name")
                : change.method;
        const MethodSpec spec = ToMethod(method, change.training, change.plates);
        if (from.spectrum.sameGrid(to.spectrum) && from.spectrum.values() == to.spectrum.values())
        {
            continue;
        }
        const auto relighter = std::make_shared<Relighter>(
            from, to, spec, FindRgbSpace(change.working), ToObserver(change.observer));
        works[name] = jobs::RgbWork([relighter](float* p, size_t n) { relighter->apply(p, n, 1); },
                                    change.threads);
    }
    return works;
}

/// The job's buffer (BufferLayout): per pixel the beauty (as given, or the
/// groups' sum), then each group's R, G, B.
std::vector<float> Interleave(const GroupImages& images)
{
    const std::vector<F32>& arrays = images.arrays;
    const size_t count = images.count;
    const size_t channels = images.channels();
    std::vector<float> buffer(count * channels);
    for (size_t g = 0; g < arrays.size(); ++g)
    {
        const float* src = arrays[g].data();
        for (size_t p = 0; p < count; ++p)
        {
            std::copy_n(src + 3 * p, 3, &buffer[p * channels + 3 + 3 * g]);
        }
    }
    for (size_t p = 0; p < count; ++p)
    {
        for (int c = 0; c < 3; ++c)
        {
            double sum = 0.0;
            for (size_t g = 0; g < arrays.size(); ++g)
            {
                sum += buffer[p * channels + 3 + 3 * g + size_t(c)];
            }
            buffer[p * channels + size_t(c)] =
                images.beauty ? images.beauty->data()[3 * p + size_t(c)] : float(sum);
        }
    }
    return buffer;
}

/// The groups relit in `buffer` and the beauty rebuilt, the GIL released.
void RelightBuffer(const jobs::LightGroupLayout& layout,
                   const std::map<std::string, jobs::LightGroupWork>& works,
                   const GroupImages& images, std::vector<float>& buffer)
{
    py::gil_scoped_release release;
    // NaN and infinity are guarded as every pixel path guards them (the
    // count is the CLI's note; the arrays come back finite).
    (void)jobs::RelightLightGroups(layout, works, buffer.data(), images.width, images.height,
                                   int(images.channels()), "light groups");
}

/// {"beauty": array, "groups": {name: array}} from the relit buffer, each
/// array of the groups' shape.
py::dict ResultDict(const GroupImages& images, const std::vector<float>& buffer)
{
    const std::vector<py::ssize_t>& shape = images.shape;
    const size_t count = images.count;
    const size_t channels = images.channels();
    py::dict relit;
    for (size_t g = 0; g < images.names.size(); ++g)
    {
        py::array_t<float> a(shape);
        float* dst = a.mutable_data();
        for (size_t p = 0; p < count; ++p)
        {
            std::copy_n(&buffer[p * channels + 3 + 3 * g], 3, dst + 3 * p);
        }
        relit[py::str(images.names[g])] = a;
    }
    py::array_t<float> newBeauty(shape);
    float* dst = newBeauty.mutable_data();
    for (size_t p = 0; p < count; ++p)
    {
        std::copy_n(&buffer[p * channels], 3, dst + 3 * p);
    }
    py::dict out;
    out["beauty"] = newBeauty;
    out["groups"] = relit;
    return out;
}

py::dict RelightGroups(const py::dict& groups, const py::dict& changes, const py::object& beauty,
                       const std::string& method, const std::string& working,
                       const py::object& observer, const py::object& training,
                       const std::string& plates, const std::string& adaptation,
                       const py::object& camera, const std::string& cameraIdt, int threadsArg)
{
    const int threads = ToThreads(threadsArg);
    const GroupImages images = ToGroupImages(groups, beauty);
    const jobs::LightGroupLayout layout = BufferLayout(images.names);
    const PlatesArgs platesArgs{plates, adaptation, camera, cameraIdt};
    const ChangeArgs change{method, working, observer, training, platesArgs, threads};
    const std::map<std::string, jobs::LightGroupWork> works =
        ToWorks(changes, layout, images.names, change);
    std::vector<float> buffer = Interleave(images);
    RelightBuffer(layout, works, images, buffer);
    return ResultDict(images, buffer);
}
}  // namespace

void AddLightGroups(py::module_& m)
{
    m.def("relight_light_groups", &RelightGroups, py::arg("groups"), py::arg("changes"),
          py::kw_only(), py::arg("beauty") = py::none(), py::arg("method") = defaults::METHOD,
          py::arg("working_space") = defaults::WORKING_SPACE,
          py::arg("observer") = defaults::OBSERVER, py::arg("training") = py::none(),
          py::arg("plates") = defaults::LIGHT_GROUP_PLATES,
          py::arg("adaptation") = defaults::ADAPTATION, py::arg("camera") = py::none(),
          py::arg("camera_idt") = defaults::IDT_LIGHT, py::arg("threads") = defaults::THREADS,
          R"doc(Relights light groups in memory, each from its own light to a new one.

groups: {name: array of R, G, B in its last dimension}, every group the same
shape (layers of one image, working-space linear RGB). changes: {name: (src,
dst)} or {name: (src, dst, method)} (a group's own method, as apply's
light_groups take it), the lights as relight() takes them; groups not named are carried
unchanged, and a group relit to its own light too. beauty: the image the
groups sum to (same shape); what they do not hold, beauty - sum(groups), is
kept as the residual. None: the sum of the groups.

Returns {"beauty": sum of relit groups + residual, "groups": {name: relit
array}}: plain dicts of numpy arrays, which pickle (for Dask). Raises
ValueError when the groups sum to more than the beauty beyond float rounding
(not a partition of it), naming the pixel; NaN and infinity are taken as
-1e16 and +-1e16, as every pixel path takes them, so the result is finite.
plates defaults to lit: a render's group carries its own light's cast.)doc");
}

}  // namespace bandlight::python
