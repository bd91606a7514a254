// SPDX-License-Identifier: BSD-3-Clause
// `wall` as a C++ host calls it, on synthetic walls of Gaussian emitters
// (stated below) and rawtoaces' ARRI D21: the in-frustum drive is exact
// (3 emitters) or the least non-negative exact one (4), both corrections lower the
// out-of-frustum error and do no worse than a plain least-squares fit of
// their form, and the written config — validated, read back — gives each
// white balance's transforms through the context variable, equal to its
// files.
// Covers, through the entry points it calls: camera/Wall.cpp, camera/WallFit.cpp,
// plugin/WallConfig.cpp, report/WallReport.cpp, requests/Wall.cpp.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>

#include <Eigen/LU>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "camera/Wall.h"
#include "jobs/JobsTestSupport.h"
#include "jobs/WallJob.h"
#include "plugin/ConfigBuilder.h"
#include "plugin/WallConfig.h"
#include "requests/Inputs.h"
#include "spectral/CameraFile.h"
#include "spectral/Exception.h"
#include "transforms/Camera.h"
#include "transforms/Idt.h"

using namespace bandlight;
using Catch::Matchers::Contains;
using test::Fresh;

namespace fs = std::filesystem;

namespace
{

const std::string kD21 = BANDLIGHT_TEST_DATA_ROOT "/rawtoaces/arri_d21_380_780_5.json";

/// A Gaussian emitter of centre `centre` and full width at half maximum
/// `fwhm` (nm), peak `peak`, 380–780 nm every 1 nm.
double Gaussian(double l, double centre, double fwhm, double peak = 1.0)
{
    const double sigma = fwhm / (2.0 * std::sqrt(2.0 * std::log(2.0)));
    return peak * std::exp(-0.5 * (l - centre) * (l - centre) / (sigma * sigma));
}

std::string WriteEmitter(const std::string& dir, const std::string& name,
                         const std::function<double(double)>& f)
{
    fs::create_directories(dir);
    const std::string path = dir + "/" + name + ".csv";
    std::ofstream o(path);
    o << "wavelength," << name << "\n";
    for (int l = 380; l <= 780; ++l)
    {
        o << l << "," << f(l) << "\n";
    }
    return path;
}

/// The emitters of the tests: R 630/20 nm, G 530/30, B 460/20 (centre /
/// FWHM), and a phosphor-white-like W: a 450/20 blue pump plus a broad
/// 570/110 phosphor at 0.55 of its peak; two greens 2 nm apart for the
/// collinear case.
std::vector<jobs::WallEmitterSpec> Emitters(const std::string& dir, bool white)
{
    std::vector<jobs::WallEmitterSpec> e = {
        {"R", WriteEmitter(dir, "red", [](double l) { return Gaussian(l, 630, 20); })},
        {"G", WriteEmitter(dir, "green", [](double l) { return Gaussian(l, 530, 30); })},
        {"B", WriteEmitter(dir, "blue", [](double l) { return Gaussian(l, 460, 20); })}};
    if (white)
    {
        e.push_back(
            {"W", WriteEmitter(dir, "white",
                               [](double l)
                               { return Gaussian(l, 450, 20) + Gaussian(l, 570, 110, 0.55); })});
    }
    return e;
}

jobs::WallRequest Request(const std::string& name, bool white)
{
    jobs::WallRequest r;
    const std::string dir = Fresh("wall_" + name);
    r.emitters = Emitters(dir + "_emitters", white);
    r.camera = kD21;
    r.whiteBalances = {"5600K", "3200K"};
    r.contentSpace = "rec709";
    r.out = dir;
    return r;
}

/// The camera's balanced RGB of each emitter at drive 1 (3 × N), from the
/// camera file and the emitter files alone.
Eigen::Matrix3Xd Response(const jobs::WallRequest& r, const Spectrum& whiteBalance)
{
    const SpectralCamera camera(ReadCameraFile(r.camera));
    const CameraShot shot(camera, whiteBalance);
    Eigen::Matrix3Xd c(3, Eigen::Index(r.emitters.size()));
    for (size_t k = 0; k < r.emitters.size(); ++k)
    {
        const Spectrum e = ReadSpectraFile(r.emitters[k].file).front().spectrum;
        Vec3 v = Vec3::Zero();
        for (int i = 0; i < SurfaceRenderer::kSamples; ++i)
        {
            v += camera.sensitivities().col(i) * e(SurfaceRenderer::Wavelength(i));
        }
        c.col(Eigen::Index(k)) = shot.gains().cwiseProduct(v);
    }
    return c;
}

/// What an OCIO processor of the written config does to RGBA pixels, with
/// the context variable set to `key`.
Eigen::Vector4d Apply(const OCIO::ConstConfigRcPtr& config, const std::string& key, const char* src,
                      const char* dst, const Eigen::Vector4d& in)
{
    OCIO::ContextRcPtr context = config->getCurrentContext()->createEditableCopy();
    context->setStringVar("WALL_WB", key.c_str());
    const OCIO::ConstCPUProcessorRcPtr cpu =
        config->getProcessor(context, src, dst)->getDefaultCPUProcessor();
    float px[4] = {float(in(0)), float(in(1)), float(in(2)), float(in(3))};
    cpu->applyRGBA(px);
    return {px[0], px[1], px[2], px[3]};
}

/// A file of the package read back through OCIO's own reader.
Eigen::Vector4d ApplyFile(const std::string& path, const Eigen::Vector4d& in)
{
    OCIO::FileTransformRcPtr f = OCIO::FileTransform::Create();
    f->setSrc(path.c_str());
    const OCIO::ConstCPUProcessorRcPtr cpu =
        OCIO::Config::CreateRaw()->getProcessor(f)->getDefaultCPUProcessor();
    float px[4] = {float(in(0)), float(in(1)), float(in(2)), float(in(3))};
    cpu->applyRGBA(px);
    return {px[0], px[1], px[2], px[3]};
}

double Relative(const Eigen::VectorXd& got, const Eigen::VectorXd& want)
{
    return (got - want).norm() / want.norm();
}

/// The checks every wall passes, whatever its emitters.
void CheckOutOfFrustum(const jobs::WallResult& result)
{
    for (const jobs::WallBalance& b : result.balances)
    {
        INFO("white balance " << b.light);
        // Each correction lowers the error on the data it was fitted on,
        // and is no worse there than the plain least-squares fit of its form.
        CHECK(b.preFit.after.mean < b.preFit.before.mean);
        CHECK(b.preFit.after.mean <= b.preFit.leastSquares.mean);
        CHECK(b.postFit.after.mean < b.postFit.before.mean);
        CHECK(b.postFit.after.mean <= b.postFit.leastSquares.mean);
        // The root polynomial is the method registry's rootpoly-plate op,
        // measured on the wall's plates: its fit's figures to rounding.
        CHECK(b.postRootPolynomialFit.after.mean <=
              b.postRootPolynomialFit.leastSquares.mean + 1e-9);
        CHECK(b.postRootPolynomialFit.after.mean < b.postRootPolynomialFit.before.mean);
        CHECK(b.postMethod.name == "rootpoly-plate");
        // The method registry's rootpoly-camera for the same change of light
        // helps too (its target is the observer's colour, not this camera's).
        CHECK(b.postRegistry.mean < b.postFit.before.mean);
        CHECK(b.postRegistry.count == b.postFit.before.count);
        // The wall showing the white balance's own light: both corrections
        // help on the training set and on the test set no correction saw.
        const jobs::WallShown* own = nullptr;
        for (const jobs::WallShown& s : b.shown)
        {
            own = s.light == b.light ? &s : own;
        }
        REQUIRE(own);
        REQUIRE(own->errors.size() == 2);
        for (const jobs::WallSetErrors& e : own->errors)
        {
            INFO(e.set);
            CHECK(e.before.mean > 0.5);
            CHECK(e.preCorrected.mean < e.before.mean);
            CHECK(e.postCorrected.mean < e.before.mean);
        }
        CHECK(own->errors[0].postCorrected.mean == Approx(b.postFit.after.mean));
    }
}

/// The drive of four emitters is the least of the non-negative exact
/// drives, found here on its own terms: the exact drives of a content
/// primary are d + z·v (v spanning the response's null space),
/// non-negative on an interval of z; the smallest |d + z·v| there is the
/// unconstrained minimiser clamped to the interval, which must be z = 0.
void CheckLeastNonNegative(const Eigen::Matrix3Xd& response, const Eigen::MatrixXd& drive)
{
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(response);
    const Eigen::MatrixXd kernel = lu.kernel();
    REQUIRE(kernel.cols() == 1);
    const Eigen::VectorXd v = kernel.col(0);
    for (int k = 0; k < 3; ++k)
    {
        INFO("content primary " << k);
        const Eigen::VectorXd d = drive.col(k);
        double lo = -INFINITY;
        double hi = INFINITY;
        for (int j = 0; j < 4; ++j)
        {
            if (v(j) > 0.0)
            {
                lo = std::max(lo, -d(j) / v(j));
            }
            else if (v(j) < 0.0)
            {
                hi = std::min(hi, -d(j) / v(j));
            }
        }
        REQUIRE(lo <= hi + 1e-12);
        const double z = std::clamp(-d.dot(v) / v.dot(v), lo, hi);
        CHECK(std::abs(z) * v.norm() < 1e-9 * d.norm());
    }
}

}  // namespace

TEST_CASE("wall: an RGB wall's in-frustum drive makes the camera record the content exactly",
          "[jobs][wall]")
{
    const jobs::WallRequest r = Request("rgb", false);
    const jobs::WallResult result = jobs::MakeWall(r);
    REQUIRE(result.balances.size() == 2);
    CHECK(result.drives == "RGB");
    const Mat3 contentToWorking = SpaceToSpace(FindRgbSpace("rec709"), FindRgbSpace("aces2065-1"));
    for (const jobs::WallBalance& b : result.balances)
    {
        INFO("white balance " << b.light);
        const jobs::WallInFrustum& f = b.inFrustum;
        CHECK(f.solution == "exact");
        REQUIRE(f.drive.rows() == 3);
        // Camera RGB of the wall driven by the transform = the record the
        // content asks for (the IDT's inverse of the content in ACES), times
        // the one exposure: every corner and grey, 1e-6 relative.
        const Eigen::Matrix3Xd c = Response(r, IdtLightForCct(b.light == "5600K" ? 5600 : 3200));
        const Mat3 intended = b.idt.matrix.inverse() * contentToWorking;
        for (const Vec3& content : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(1, 1, 1),
                                   Vec3(0.18, 0.18, 0.18), Vec3(0.2, 0.5, 0.9)})
        {
            INFO(content.transpose());
            CHECK(Relative(c * (f.drive * content), f.exposure * intended * content) < 1e-6);
        }
        CHECK(f.residual < 1e-9);
        CHECK(f.condition > 1.0);
        CHECK(f.condition < 10.0);
        // Content white drives the most driven emitter at 1.
        CHECK((f.drive * Vec3::Ones()).maxCoeff() == Approx(1.0));
        CHECK(f.corners.size() == 7);
    }
    CheckOutOfFrustum(result);
}

TEST_CASE("wall: an RGBW wall gets the least non-negative exact drive, its fourth drive in alpha",
          "[jobs][wall]")
{
    const jobs::WallRequest r = Request("rgbw", true);
    const jobs::WallResult result = jobs::MakeWall(r);
    CHECK(result.drives == "RGBA");
    CHECK_THAT(result.configNote, Contains("alpha"));
    const OCIO::ConstConfigRcPtr config = jobs::LoadConfig(r.out);
    config->validate();
    for (const jobs::WallBalance& b : result.balances)
    {
        INFO("white balance " << b.light);
        const jobs::WallInFrustum& f = b.inFrustum;
        CHECK(f.solution == "non-negative minimum-norm");
        REQUIRE(f.drive.rows() == 4);
        const Eigen::Matrix3Xd c = Response(r, IdtLightForCct(b.light == "5600K" ? 5600 : 3200));
        const Mat3 intended = b.idt.matrix.inverse() *
                              SpaceToSpace(FindRgbSpace("rec709"), FindRgbSpace("aces2065-1"));
        // Exact: response · D = exposure · intended.
        CHECK((c * f.drive - f.exposure * intended).norm() < 1e-9 * (f.exposure * intended).norm());
        // Non-negative: every colour of the content cube gets a drive a wall
        // can emit (the drive is linear in the content).
        CHECK(f.drive.minCoeff() >= 0.0);
        CHECK(f.negativeCorners == 0);
        CheckLeastNonNegative(c, f.drive);
        // Where the exact equations allow negative drives, the smallest
        // (Moore–Penrose) drive takes one: non-negativity is a real choice.
        const Eigen::MatrixXd pinv = c.transpose() * (c * c.transpose()).inverse() * intended;
        CHECK(pinv.minCoeff() < 0.0);
        // The config's drive: R, G, B and W in alpha, as the CTF file holds it.
        const Eigen::Vector4d content(0.2, 0.5, 0.9, 1.0);
        const Eigen::Vector4d drive =
            Apply(config, b.key, "Linear Rec.709 (sRGB)", kWallDriveSpace, content);
        const Eigen::VectorXd want = f.drive * content.head<3>();
        CHECK(Relative(drive, want) < 1e-5);
        CHECK(Relative(ApplyFile(r.out + "/" + WallFile(b.key, "in_frustum", true), content),
                       want) < 1e-5);
        // The lighting drive: the pre-correction after it.
        const Eigen::Vector4d lighting =
            Apply(config, b.key, "Linear Rec.709 (sRGB)", kWallLightingSpace, content);
        CHECK(Relative(lighting, b.preCorrection * want) < 1e-5);
    }
    CheckOutOfFrustum(result);
}

TEST_CASE("wall: the config switches its transforms with WALL_WB, each equal to its files",
          "[jobs][wall]")
{
    const jobs::WallRequest r = Request("config", false);
    const jobs::WallResult result = jobs::MakeWall(r);
    const OCIO::ConstConfigRcPtr config = jobs::LoadConfig(r.out);
    config->validate();
    REQUIRE(std::string(config->getEnvironmentVarDefault("WALL_WB")) == "5600K");
    const std::string input = IdtColorSpaceName(result.camera, "wall white balance");
    std::vector<Eigen::Vector4d> drives;
    for (const jobs::WallBalance& b : result.balances)
    {
        INFO("white balance " << b.key);
        for (const Eigen::Vector4d& px :
             {Eigen::Vector4d(1, 0, 0, 1), Eigen::Vector4d(0, 1, 0, 1), Eigen::Vector4d(0, 0, 1, 1),
              Eigen::Vector4d(0.3, 0.6, 0.1, 1)})
        {
            // In frustum: the drive matrix, and its CLF file.
            const Eigen::Vector4d drive =
                Apply(config, b.key, "Linear Rec.709 (sRGB)", kWallDriveSpace, px);
            Eigen::Vector4d want;
            want << b.inFrustum.drive * px.head<3>(), 1.0;
            CHECK(Relative(drive, want) < 1e-5);
            CHECK(Relative(ApplyFile(r.out + "/" + WallFile(b.key, "in_frustum", false), px),
                           want) < 1e-5);
            if (px(0) == 0.3)
            {
                drives.push_back(drive);
            }
            // The lighting drive.
            Eigen::Vector4d lit;
            lit << b.preCorrection * b.inFrustum.drive * px.head<3>(), 1.0;
            CHECK(Relative(Apply(config, b.key, "Linear Rec.709 (sRGB)", kWallLightingSpace, px),
                           lit) < 1e-5);
            // The camera's IDT for this white balance, gains folded in.
            Eigen::Vector4d aces;
            aces << b.idt.rawToWorking() * px.head<3>(), 1.0;
            CHECK(Relative(Apply(config, b.key, input.c_str(), "ACES2065-1", px), aces) < 1e-5);
        }
        // The post-camera look through the config's look processor.
        OCIO::ContextRcPtr context = config->getCurrentContext()->createEditableCopy();
        context->setStringVar("WALL_WB", b.key.c_str());
        OCIO::LookTransformRcPtr look = OCIO::LookTransform::Create();
        look->setSrc("ACES2065-1");
        look->setDst("ACES2065-1");
        look->setLooks(kWallPostLook);
        const Mat3 post =
            MeasureMatrix(config->getProcessor(context, look, OCIO::TRANSFORM_DIR_FORWARD));
        CHECK((post - b.post).cwiseAbs().maxCoeff() < 1e-5 * b.post.cwiseAbs().maxCoeff());
        // Its root-polynomial form, a 3D LUT with a shaper: the wall's root
        // polynomial to the LUT's interpolation error, on plates from deep
        // shadow to highlights (ACES2065-1). The log2 shaper's cells span a
        // third of a stop, across which a map that mixes channels is
        // interpolated to under 1 % of the pixel (as every non-linear look
        // of a config is: docs/accuracy.md gives it in ΔE00).
        look->setLooks(kWallPostRootPolyLook);
        const OCIO::ConstCPUProcessorRcPtr rootpoly =
            config->getProcessor(context, look, OCIO::TRANSFORM_DIR_FORWARD)
                ->getDefaultCPUProcessor();
        double worst = 0.0;
        Eigen::RowVector3d where = Eigen::RowVector3d::Zero();
        for (const double exposure : {0.01, 0.18, 1.0, 8.0})
        {
            for (const Vec3& plate : {Vec3(0.9, 0.6, 0.4), Vec3(0.3, 0.5, 0.2), Vec3(0.2, 0.3, 0.8),
                                      Vec3(0.5, 0.5, 0.5), Vec3(0.7, 0.2, 0.25)})
            {
                const Vec3 in = exposure * plate;
                float px[3] = {float(in(0)), float(in(1)), float(in(2))};
                rootpoly->applyRGB(px);
                const Vec3 want = b.postRootPolynomial.apply(in);
                const double d = (Vec3(px[0], px[1], px[2]) - want).cwiseAbs().maxCoeff() /
                                 want.cwiseAbs().maxCoeff();
                if (d > worst)
                {
                    worst = d;
                    where = in.transpose();
                }
            }
        }
        INFO("root polynomial look, worst relative difference " << worst << " at " << where);
        CHECK(worst < 1e-2);
        CHECK(worst > 0.0);  // a LUT, not the polynomial itself
        // Each file says what it was made from.
        std::ifstream in(r.out + "/" + WallFile(b.key, "post_camera", false));
        const std::string clf((std::istreambuf_iterator<char>(in)), {});
        CHECK_THAT(clf, Contains("Emitters R, G, B"));
        CHECK_THAT(clf, Contains("camera arri d21"));
        CHECK_THAT(clf, Contains("white-balanced for " + b.light));
        CHECK_THAT(clf, Contains("rawtoaces 190"));
        CHECK_THAT(clf, Contains("dE00 mean"));
        std::ifstream lut(r.out + "/" + WallFile(b.key, "post_camera_rootpoly", false));
        const std::string lutText((std::istreambuf_iterator<char>(lut)), {});
        CHECK_THAT(lutText, Contains("root polynomial"));
        CHECK_THAT(lutText, Contains("white-balanced for " + b.light));
        CHECK_THAT(lutText, Contains("^3 LUT, shaper"));
    }
    // Two white balances, two transforms.
    REQUIRE(drives.size() == 2);
    CHECK(Relative(drives[0], drives[1]) > 1e-3);
}

TEST_CASE("wall: report.json holds the conventions, the context variable and every error",
          "[jobs][wall]")
{
    const jobs::WallRequest r = Request("report", false);
    const jobs::WallResult result = jobs::MakeWall(r);
    std::ifstream in(r.out + "/report.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    CHECK(j["camera"] == "arri d21");
    CHECK(j["content_space"] == "rec709");
    CHECK(j["emitters"].size() == 3);
    CHECK(j["context_variable"]["name"] == "WALL_WB");
    CHECK(j["context_variable"]["values"] == nlohmann::json({"5600K", "3200K"}));
    CHECK(j["context_variable"]["default"] == "5600K");
    CHECK(j["training"]["count"] == 190);
    CHECK(j["test_set"]["name"] == "TCS");
    for (const char* c :
         {"in_frustum", "depicted_light", "reference", "error", "pre_correction", "post_camera"})
    {
        CHECK(j["conventions"][c].is_string());
    }
    REQUIRE(j["white_balances"].size() == 2);
    for (const nlohmann::json& w : j["white_balances"])
    {
        const nlohmann::json& f = w["in_frustum"];
        CHECK(f["residual"].get<double>() < 1e-9);
        CHECK(f["drive_matrix"].size() == 3);
        CHECK(f["condition_number"].get<double>() > 1.0);
        CHECK(f["corners"].size() == 7);
        CHECK(f["negative_share"].get<double>() >= 0.0);
        CHECK(w["pre_correction"]["matrix"].size() == 3);
        CHECK(w["post_camera"]["matrix"].size() == 3);
        REQUIRE(w["out_of_frustum"].size() == 2);
        for (const nlohmann::json& s : w["out_of_frustum"])
        {
            for (const char* set : {"rawtoaces 190", "TCS"})
            {
                for (const char* when : {"before", "pre_corrected", "post_corrected"})
                {
                    const nlohmann::json& e = s["errors"][set][when];
                    CHECK(e["mean"].get<double>() > 0.0);
                    CHECK(e["max"].get<double>() >= e["p95"].get<double>());
                }
            }
        }
    }
    CHECK(result.written.size() == 2 + 2 + 5 * 2);  // config, report, idt's spaces, 5 a balance
}

TEST_CASE("wall: more than four emitters are solved and reported, not put in the config",
          "[jobs][wall]")
{
    jobs::WallRequest r = Request("six", true);
    const std::string dir = r.out + "_emitters";
    r.emitters.push_back(
        {"A", WriteEmitter(dir, "amber", [](double l) { return Gaussian(l, 592, 16); })});
    r.emitters.push_back(
        {"C", WriteEmitter(dir, "cyan", [](double l) { return Gaussian(l, 505, 28); })});
    r.whiteBalances = {"5600K"};
    const jobs::WallResult result = jobs::MakeWall(r);
    CHECK(result.drives.empty());
    CHECK_THAT(result.configNote, Contains("6 emitters"));
    CHECK_THAT(result.configNote, Contains("report.json"));
    const jobs::WallBalance& b = result.balances.front();
    CHECK(b.inFrustum.drive.rows() == 6);
    CHECK(b.preCorrection.rows() == 6);
    CHECK(b.inFrustum.residual < 1e-9);
    const OCIO::ConstConfigRcPtr config = jobs::LoadConfig(r.out);
    config->validate();
    CHECK(!config->getColorSpace(kWallDriveSpace));
    CHECK(!config->getColorSpace(kWallLightingSpace));
    CHECK(config->getLook(kWallPostLook));
    CHECK(!fs::exists(r.out + "/" + WallFile(b.key, "in_frustum", false)));
    std::ifstream in(r.out + "/report.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    CHECK(j["config"]["drives"].is_null());
    CHECK(j["white_balances"][0]["in_frustum"]["drive_matrix"].size() == 6);
    CheckOutOfFrustum(result);
}

TEST_CASE("wall: the least non-negative drive, whatever the emitter files' units",
          "[jobs][wall]")
{
    // Four emitters as a camera sees them (balanced RGB per unit drive):
    // three primaries and a white, and content whose record four positive
    // drives make, so that the least exact drive may use all four.
    Eigen::Matrix3Xd r(3, 4);
    // clang-format off
    r << 1.0,  0.2, 0.02, 0.6,
         0.1,  1.0, 0.1,  0.7,
         0.02, 0.1, 1.0,  0.5;
    // clang-format on
    Eigen::MatrixXd d0(4, 3);
    // clang-format off
    d0 << 0.5,  0.1, 0.05,
          0.1,  0.6, 0.1,
          0.05, 0.1, 0.7,
          0.3,  0.3, 0.3;
    // clang-format on
    const Mat3 record = r * d0;
    const std::vector<std::string> names = {"R", "G", "B", "W"};
    const jobs::WallInFrustum f = jobs::SolveInFrustum(r, record, names, "test camera");
    CHECK(f.solution == "non-negative minimum-norm");
    CHECK(f.residual < 1e-12);
    CHECK(f.drive.minCoeff() >= 0.0);
    CheckLeastNonNegative(r, f.drive);
    // Here the smallest exact drive is already non-negative (the
    // Moore–Penrose one): every emitter is driven for every primary.
    const Eigen::MatrixXd pinv = r.transpose() * (r * r.transpose()).inverse() * record;
    REQUIRE(pinv.minCoeff() > 0.0);
    CHECK((f.drive - f.exposure * pinv).norm() < 1e-12 * f.drive.norm());
    // The emitter files' units change the exposure, nothing else.
    for (const double k : {1e-3, 1e3})
    {
        INFO("emitters scaled by " << k);
        const jobs::WallInFrustum g = jobs::SolveInFrustum(k * r, k * record, names, "test camera");
        CHECK(g.solution == f.solution);
        CHECK((g.drive - f.drive).norm() < 1e-12 * f.drive.norm());
        const jobs::WallInFrustum h = jobs::SolveInFrustum(k * r, record, names, "test camera");
        CHECK((h.drive - f.drive).norm() < 1e-12 * f.drive.norm());
        CHECK(h.exposure == Approx(k * f.exposure).epsilon(1e-12));
    }
}

TEST_CASE("wall: content wider than the emitters gets the closest non-negative drive",
          "[jobs][wall]")
{
    // Rec.2020's primaries lie outside what the RGBW wall can show this
    // camera: no exact drive is non-negative.
    jobs::WallRequest r = Request("wide", true);
    r.contentSpace = "rec2020";
    r.whiteBalances = {"5600K"};
    const jobs::WallResult result = jobs::MakeWall(r);
    const jobs::WallBalance& b = result.balances.front();
    const jobs::WallInFrustum& f = b.inFrustum;
    CHECK(f.solution == "non-negative least-squares");
    CHECK(f.drive.minCoeff() >= 0.0);
    CHECK(f.negativeCorners == 0);
    CHECK(f.residual > 1e-3);
    // Optimal, by Karush–Kuhn–Tucker's conditions for min |R d − t| over
    // d ≥ 0, checked from the camera and emitter files alone: the gradient
    // Rᵀ(R d − t) is zero where an emitter is driven and not negative where
    // it is dark (no non-negative step lowers the error).
    const Eigen::Matrix3Xd c = Response(r, IdtLightForCct(5600));
    const Mat3 target = f.exposure * b.idt.matrix.inverse() *
                        SpaceToSpace(FindRgbSpace("rec2020"), FindRgbSpace("aces2065-1"));
    for (int k = 0; k < 3; ++k)
    {
        INFO("content primary " << k);
        const Eigen::VectorXd d = f.drive.col(k);
        const Eigen::VectorXd g = c.transpose() * (c * d - target.col(k));
        const double scale = (c.transpose() * target.col(k)).cwiseAbs().maxCoeff();
        for (Eigen::Index j = 0; j < d.size(); ++j)
        {
            INFO("emitter " << j << " drive " << d(j) << " gradient " << g(j));
            if (d(j) > 1e-9)
            {
                CHECK(std::abs(g(j)) < 1e-6 * scale);
            }
            else
            {
                CHECK(g(j) > -1e-6 * scale);
            }
        }
    }
}

TEST_CASE("wall: emitters the camera sees nearly alike are refused with the condition number",
          "[jobs][wall]")
{
    jobs::WallRequest r = Request("collinear", false);
    r.emitters[2] = {"G2", WriteEmitter(r.out + "_emitters", "green2",
                                        [](double l) { return Gaussian(l, 532, 30); })};
    REQUIRE_THROWS_WITH(jobs::MakeWall(r), Contains("nearly collinear") &&
                                               Contains("condition number") &&
                                               Contains("G and G2"));
    CHECK(!fs::exists(r.out));
}
