// SPDX-License-Identifier: BSD-3-Clause
// The image module's loader, and what the library writes through it.
#include "imageio/ImageFiles.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>

#include "spectral/Exception.h"

namespace bandlight
{

void WriteImage(const std::string& path, const float* pixels, int width, int height, int channels,
                const std::vector<std::string>& channelNames, ImageDescription description,
                PixelType type, OutputSet* outputs)
{
    const ImageFilesApi& api = ImageFiles();
    if (outputs)
    {
        AtomicFile& file = outputs->add(path);
        file.stream().close();  // the module writes by name
        description.writeAs = file.tempPath();
    }
    ThrowIfFailed(
        api.write(path, pixels, width, height, channels, channelNames, description, type));
}

ImageDescription LinearImageDescription(const RgbSpace& space, const std::string& name)
{
    ImageDescription d;
    d.colorSpace = name;
    const Chromaticities& c = space.chromaticities;
    d.chromaticities = {float(c.rx), float(c.ry), float(c.gx), float(c.gy),
                        float(c.bx), float(c.by), float(c.wx), float(c.wy)};
    // OpenImageIO 2.4 drops oiio:ColorSpace when it writes an EXR (and
    // reads every EXR back as "Linear"): the name is also kept as
    // bandlight:colorSpace, and the Color Interop Forum ID as colorInteropID,
    // which later OpenImageIO versions read.
    d.attributes.push_back({"bandlight:colorSpace", name});
    for (const InteropId& id : space.interopIds)
    {
        if (!id.srgbEncoded)
        {
            d.attributes.push_back({"colorInteropID", id.id});
            break;
        }
    }
    return d;
}

void ThrowIfFailed(const ImageFilesStatus& status)
{
    if (status.fileError)
    {
        throw FileError::WithMessage(status.path, status.error, status.message);
    }
    if (!status.message.empty())
    {
        throw Exception(status.message);
    }
}

const ImageFilesApi& ImageFiles()
{
    static const ImageFilesApi* api = []
    {
        // The module sits beside the executable in a build tree, in
        // ../lib/bandlight when installed, or where the environment says.
        std::vector<std::string> places;
        if (const char* env = std::getenv("BANDLIGHT_IMAGE_MODULE"))
        {
            places.push_back(env);
        }
        char exe[4096];
        const ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (n > 0)
        {
            exe[n] = '\0';
            std::string dir(exe);
            dir = dir.substr(0, dir.find_last_of('/'));
            places.push_back(dir + "/libbandlight_images.so");
            places.push_back(dir + "/../lib/bandlight/libbandlight_images.so");
        }
        // A library loaded into another program (the Python module in its
        // package folder) finds the module beside itself.
        Dl_info self{};
        if (::dladdr(reinterpret_cast<const void*>(&ImageFiles), &self) && self.dli_fname)
        {
            std::string dir(self.dli_fname);
            const size_t slash = dir.find_last_of('/');
            dir = slash == std::string::npos ? "." : dir.substr(0, slash);
            places.push_back(dir + "/libbandlight_images.so");
        }
        std::string tried;
        for (const std::string& p : places)
        {
            if (void* h = ::dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL))
            {
                using Entry = const ImageFilesApi* (*)();
                auto entry = reinterpret_cast<Entry>(::dlsym(h, "bandlight_image_files_api"));
                if (entry && entry()->version == kImageFilesApiVersion)
                {
                    AlsoOnInterrupt(entry()->removeTemporaryFiles);
                    return entry();
                }
            }
            const char* err = ::dlerror();
            tried += (tried.empty() ? "" : "; ") + std::string(err ? err : p.c_str());
        }
        throw Exception("cannot load the image module libbandlight_images.so (" + tried + ")");
    }();
    return *api;
}

}  // namespace bandlight
