// SPDX-License-Identifier: BSD-3-Clause
// `bandlight render`: Phong with coloured lights in band or spectral mode,
// planned so only the effects the scene calls for are simulated (the render
// job, jobs/RenderJob.h).
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "jobs/RenderJob.h"
#include "spectral/Parallel.h"
#include "cli/Commands.h"
#include "cli/Common.h"

namespace bandlight::cli
{

namespace
{

struct RenderOptions
{
    jobs::RenderRequest request;
    std::string mode;  ///< empty: the scene's
};

void RunRender(const RenderOptions& o)
{
    jobs::RenderRequest r = o.request;
    r.mode = o.mode.empty() ? std::nullopt : std::optional<std::string>(o.mode);
    if (r.out.empty())
    {
        r.out = jobs::DefaultRenderOutput(r.scene);
    }
    // The plan is printed before the work.
    const jobs::PreparedRender prepared = jobs::PrepareRender(r);
    std::cout << prepared.explanation;
    if (r.explain)
    {
        return;
    }
    CommandReporter reporter;
    const jobs::RenderResult result = jobs::MakeRender(prepared, reporter);
    const RenderCounters& c = result.counters;
    std::cout << "rendered " << c.pixels << " pixels (" << c.hits << " hits) in "
              << Fixed(result.seconds * 1e3, 1) << " ms: " << c.lightTerms << " light terms, "
              << c.specularTerms << " specular, " << c.attenuationTerms << " attenuation, "
              << c.spectralSamples << " per-pixel spectral samples\n";
    for (const jobs::RenderFile& f : result.files)
    {
        std::cout << "Wrote " << f.path << " (" << f.what << ")\n";
    }
    if (const auto& compare = result.comparison)
    {
        const DeltaESummary& s = compare->summary;
        std::cout << "compare with spectral: " << s.pixels << " pixels, ΔE00 mean "
                  << Fixed(s.mean, 3) << ", p95 " << Fixed(s.p95, 3) << ", max " << Fixed(s.max, 3)
                  << " (" << compare->exr << ", _dE00.png: black 0, white >= 10)\n";
    }
}

}  // namespace

void AddRenderCommand(CLI::App& app)
{
    auto o = std::make_shared<RenderOptions>();
    jobs::RenderRequest& r = o->request;
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a YAML scene (Phong, coloured lights) in band or spectral mode");
    cmd->add_option("SCENE", r.scene, "Scene file (see docs/scenes.md)")->required();
    cmd->add_option("-o,--out", r.out, "Output EXR (default: SCENE.exr); an sRGB PNG goes beside");
    cmd->add_option("--mode", o->mode, "Override the scene's mode: band3, bandN or spectral");
    cmd->add_flag("--explain", r.explain,
                  "Print the plan (with --unplanned: what the literal path does) and stop");
    cmd->add_flag("--compare", r.compare,
                  "Also render the spectral reference; write a ΔE00 heat map and a summary");
    cmd->add_flag("--unplanned", r.unplanned,
                  "Evaluate every term per pixel and sample (the reference for the planner)");
    cmd->add_flag("--light-groups", r.lightGroups,
                  "One layer per light group beside the beauty: <group>.R/G/B (and "
                  "<group>.S0.<nm> with --spectra); a light's group is its group: or name: in "
                  "the scene, else light1, light2, ...; the beauty is their sum");
    cmd->add_flag("--spectra", r.spectra,
                  "Spectral mode: write the spectral radiance into the EXR too, as S0.<nm> "
                  "channels beside R, G, B (Fichet 2021 layout; read by bandlight spectral)");
    cmd->add_option("--threads", r.threads, "Threads (0: all cores; at most 256)")
        ->check(CLI::Range(0, kMaxThreads))
        ->capture_default_str();
    cmd->callback([o] { RunRender(*o); });
}

}  // namespace bandlight::cli
