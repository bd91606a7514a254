// SPDX-License-Identifier: BSD-3-Clause
// A host calling the jobs library: the config job with a default request
// writes FOLDER/config.ocio (the test compares it with the command's).
#include <iostream>

#include <bandlight/bandlight.h>

int main(int argc, char** argv)
{
    if (argc != 2)
    {
        std::cerr << "usage: config_host FOLDER\n";
        return 2;
    }
    bandlight::jobs::ConfigRequest request;
    request.out = argv[1];
    const bandlight::jobs::ConfigResult result = bandlight::jobs::MakeConfig(request);
    std::cout << result.package.config->getNumLooks() << " looks\n";
    return 0;
}
