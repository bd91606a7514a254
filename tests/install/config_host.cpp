// SPDX-License-Identifier: BSD-3-Clause
// A host of the public API: WriteConfig with nothing but the folder given
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
    bandlight::ConfigSettings settings;
    settings.out = argv[1];
    const bandlight::WrittenConfig written = bandlight::WriteConfig(settings);
    std::cout << written.looks.size() << " looks in " << written.file << "\n";
    return written.looks.empty() ? 1 : 0;
}
