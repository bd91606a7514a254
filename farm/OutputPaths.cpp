// SPDX-License-Identifier: BSD-3-Clause
#include "farm/OutputPaths.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>
#include <system_error>

#include <sys/stat.h>
#include <unistd.h>

#include "spectral/Exception.h"

namespace bandlight::jobs
{

namespace fs = std::filesystem;

namespace
{

/// The folder a file output is written into ("." for a bare name).
fs::path FolderOf(const std::string& path)
{
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? fs::path(".") : parent;
}

/// Refuses a folder that does not exist, is not a folder, or cannot be
/// written into (a FileError with the errno writing would meet); `path`
/// names the output that needs it.
void CheckWritableFolder(const std::string& path, const fs::path& folder)
{
    struct stat st{};
    if (::stat(folder.c_str(), &st) != 0)
    {
        const int e = errno;
        throw FileError(path, e,
                        "cannot write there: the folder " + ShowPath(folder.string()) + " " +
                            (e == ENOENT ? "does not exist" : std::string(std::strerror(e))));
    }
    if (!S_ISDIR(st.st_mode))
    {
        throw FileError(path, ENOTDIR,
                        "cannot write there: " + ShowPath(folder.string()) + " is not a folder");
    }
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
    {
        const int e = errno;
        throw FileError(path, e,
                        "cannot write there: the folder " + ShowPath(folder.string()) +
                            " is not writable (" + std::strerror(e) + ")");
    }
}

}  // namespace

std::string ShowPath(const std::string& path)
{
    return path.empty() ? "'' (an empty path)" : "'" + OneLine(path, 300) + "'";
}

bool SameFile(const std::string& a, const std::string& b)
{
    struct stat sa{}, sb{};
    if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0)
    {
        return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
    }
    std::error_code ec;
    const fs::path na = fs::absolute(a, ec).lexically_normal();
    const fs::path nb = fs::absolute(b, ec).lexically_normal();
    return !ec && na == nb;
}

OutputPlan& OutputPlan::file(const std::string& param, const std::string& path,
                             bool mayReplaceInput)
{
    m_outputs.push_back({param, path, false, mayReplaceInput});
    return *this;
}

OutputPlan& OutputPlan::folder(const std::string& param, const std::string& path,
                               const std::vector<std::string>& contents)
{
    m_outputs.push_back({param, path, true, false});
    // The files it will hold can be one of the run's inputs only when the
    // folder exists already.
    std::error_code ec;
    if (!path.empty() && fs::is_directory(path, ec))
    {
        for (const std::string& name : contents)
        {
            m_outputs.push_back({param, (fs::path(path) / name).string(), false, false});
        }
    }
    return *this;
}

OutputPlan& OutputPlan::input(const std::string& path)
{
    m_inputs.push_back(path);
    return *this;
}

namespace
{
/// A file's identity: device and inode when it exists, else its absolute,
/// normalised path (two names of one file compare equal either way).
struct FileKey
{
    dev_t dev = 0;
    ino_t ino = 0;
    std::string path;

    bool operator<(const FileKey& o) const
    {
        return std::tie(dev, ino, path) < std::tie(o.dev, o.ino, o.path);
    }
};

FileKey KeyOf(const std::string& path)
{
    struct stat st{};
    if (::stat(path.c_str(), &st) == 0)
    {
        return {st.st_dev, st.st_ino, ""};
    }
    std::error_code ec;
    return {0, 0, fs::absolute(path, ec).lexically_normal().string()};
}
}  // namespace

void OutputPlan::check() const
{
    std::map<FileKey, const std::string*> inputs;
    for (const std::string& in : m_inputs)
    {
        inputs.emplace(KeyOf(in), &in);
    }
    std::map<FileKey, const Output*> outputs;
    std::set<std::string> folders;  // checked once each
    for (const Output& o : m_outputs)
    {
        if (o.path.empty())
        {
            throw ParameterError(o.param + " is '' (an empty path): name the " +
                                 (o.folder ? "folder" : "file") + " to write");
        }
        std::error_code ec;
        const fs::file_status st = fs::status(o.path, ec);
        if (o.folder)
        {
            if (fs::exists(st) && !fs::is_directory(st))
            {
                throw FileError::ForParameter(o.path, ENOTDIR,
                                              o.param + " " + ShowPath(o.path) +
                                                  " is a file, not a folder");
            }
            // The nearest existing ancestor is where the folder is created.
            fs::path existing = fs::absolute(o.path, ec).lexically_normal();
            while (!fs::exists(existing, ec) && existing.has_parent_path() &&
                   existing != existing.parent_path())
            {
                existing = existing.parent_path();
            }
            CheckWritableFolder(o.path, existing);
            continue;
        }
        if (fs::is_directory(st))
        {
            throw FileError::ForParameter(o.path, EISDIR,
                                          o.param + " " + ShowPath(o.path) +
                                              " is a folder, not a file");
        }
        const fs::path folder = FolderOf(o.path);
        if (folders.insert(folder.string()).second)
        {
            CheckWritableFolder(o.path, folder);
        }
        const FileKey key = KeyOf(o.path);
        if (!o.mayReplaceInput)
        {
            if (const auto in = inputs.find(key); in != inputs.end())
            {
                throw ParameterError(o.param + " " + ShowPath(o.path) + " is the input " +
                                     ShowPath(*in->second) +
                                     ": writing it would replace what the run reads; name "
                                     "another file");
            }
        }
        if (const auto [it, fresh] = outputs.emplace(key, &o); !fresh)
        {
            throw ParameterError(it->second->param + " and " + o.param + " name the same file " +
                                 ShowPath(o.path));
        }
    }
}

}  // namespace bandlight::jobs
