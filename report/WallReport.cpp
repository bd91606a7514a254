// SPDX-License-Identifier: BSD-3-Clause
#include "report/WallReport.h"

#include "report/LightQualityReport.h"
#include "report/ResultTable.h"

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "requests/Inputs.h"
#include "spectral/RgbSpaces.h"

namespace bandlight::jobs
{

namespace
{

using Json = nlohmann::ordered_json;

Json VectorJson(const Eigen::VectorXd& v)
{
    Json a = Json::array();
    for (Eigen::Index i = 0; i < v.size(); ++i)
    {
        a.push_back(v(i));
    }
    return a;
}

Json FitJson(const WallFitFigures& f)
{
    return {{"fit", f.fit},
            {"before", StatisticsJson(f.before)},
            {"after", StatisticsJson(f.after)},
            {"least_squares", StatisticsJson(f.leastSquares)}};
}

/// The conventions every figure of the report follows (docs/wall.md).
Json Conventions(const WallResult& r)
{
    const std::string working = FindRgbSpace(r.workingSpace).displayName;
    return {
        {"in_frustum",
         "The camera, white-balanced for the light named (the perfect reflector under it "
         "records 1,1,1) and read through bandlight's IDT for that light (to " +
             working + "), records the wall driven for content c as the plate c carried into " +
             working + ", times one exposure (content white drives the most driven emitter at 1)"},
        {"solution",
         "three emitters: the exact inverse; more: the non-negative drive of least error (every "
         "colour of the content cube driven non-negatively), the least drive among equals: "
         "'non-negative minimum-norm' when it is exact, 'non-negative least-squares' when no "
         "exact drive is non-negative; the condition number is of the camera's response with "
         "each emitter's column of unit length"},
        {"depicted_light",
         "the wall shows a light L with the content whose plate is that of a white card under "
         "L for this white balance, through the in-frustum transform, its largest drive 1"},
        {"reference", "the real light L at the wall's luminance (CIE Y)"},
        {"error",
         "CIEDE2000 between plates (camera white balance and IDT) of each remittance lit by the "
         "wall and by L, L*a*b* relative to the plate of a white card under L"},
        {"pre_correction",
         "an N x N matrix on the drive, fitted over the depicted lights and the training set by "
         "linear least squares, minimum norm: bandlight's fit (iteratively reweighted on "
         "CIEDE2000 to first order, minimising the mean) unless the plain fit has the lower mean "
         "dE00 on the data"},
        {"post_camera",
         "a 3x3 on the plate (working RGB), fitted for the wall showing the white-balance "
         "light, as the pre-correction is (also started from bandlight's 3x3 for a change of "
         "light); and its non-linear form, the method registry's rootpoly-plate op (a degree-2 "
         "root polynomial fitted the same way, from the camera's plates under the wall to its "
         "plates under the light: lit plates, the white balance's IDT)"},
        {"registry",
         "the method registry's rootpoly-camera op for the same change of light (the wall's "
         "spectrum to the light, the camera set, its IDT the white balance's), fitted to the "
         "observer's colours under the light, measured on the same plates for comparison"}};
}

std::string Stats(const Statistics& s)
{
    return Fixed(s.mean, 2) + " / " + Fixed(s.p95, 2) + " / " + Fixed(s.max, 2);
}

std::string Emitters(const WallResult& r)
{
    std::string names;
    for (const WallEmitterSpec& e : r.emitters)
    {
        names += (names.empty() ? "" : ", ") + e.name;
    }
    return names;
}

/// A light's scores as `quality --json` writes one light; null for none (a
/// negative drive: no light to score).
Json ScoresJson(const std::optional<LightQuality>& q)
{
    return q ? Json::parse(QualityJson({*q}))[0] : Json();
}

/// A light's headline scores in one line (Ra, R9, Rf, Rg, SSI, TLCI), or why
/// there are none.
std::string Headlines(const std::optional<LightQuality>& q)
{
    if (!q)
    {
        return "not scored (a negative drive: no light)";
    }
    std::string line;
    const auto add = [&](const char* key, const char* field, const char* label, int element)
    {
        const Score* s = q->score(key);
        const ScoreField* f = s ? s->field(field) : nullptr;
        if (!f || f->values.size() <= size_t(std::max(element, 0)))
        {
            return;
        }
        line += (line.empty() ? "" : ", ") + std::string(label) + " " +
                Fixed(f->values[size_t(std::max(element, 0))], 0);
    };
    add("cri", "Ra", "Ra", -1);
    add("cri", "R", "R9", 8);
    add("cie2017", "Rf", "Rf", -1);
    add("tm30", "Rg", "Rg", -1);
    add("ssi", "value", "SSI", -1);
    add("tlci", "Qa", "TLCI", -1);
    return line.empty() ? "no score has a value" : line;
}

}  // namespace

std::string WallDocument(const WallResult& r)
{
    Json j;
    j["camera"] = r.camera;
    j["content_space"] = r.contentSpace;
    j["working_space"] = r.workingSpace;
    j["adaptation"] = r.adaptation;
    j["emitters"] = Json::array();
    for (const WallEmitterSpec& e : r.emitters)
    {
        j["emitters"].push_back({{"name", e.name}, {"file", e.file}});
    }
    j["training"] = {{"name", r.trainingName}, {"count", r.trainingCount}};
    j["test_set"] = {{"name", r.testName}, {"count", r.testCount}};
    Json values = Json::array();
    for (const WallBalance& b : r.balances)
    {
        values.push_back(b.key);
    }
    j["context_variable"] = {{"name", r.contextVariable},
                             {"values", values},
                             {"default", r.balances.empty() ? "" : r.balances.front().key}};
    j["config"] = {{"drives", r.drives.empty() ? Json() : Json(r.drives)}, {"note", r.configNote}};
    j["conventions"] = Conventions(r);
    j["depicted_lights"] = r.depicted;
    j["white_balances"] = Json::array();
    for (const WallBalance& b : r.balances)
    {
        Json w;
        w["light"] = b.light;
        w["key"] = b.key;
        w["cct"] = b.cct;
        w["duv"] = b.duv;
        w["gains"] = {b.idt.gains.x(), b.idt.gains.y(), b.idt.gains.z()};
        w["idt"] = MatrixJson(b.idt.matrix);
        const WallInFrustum& f = b.inFrustum;
        Json corners = Json::array();
        for (const WallCorner& c : f.corners)
        {
            corners.push_back({{"name", c.name},
                               {"content", {c.content.x(), c.content.y(), c.content.z()}},
                               {"drive", VectorJson(c.drive)},
                               {"negative", c.negative}});
        }
        w["in_frustum"] = {
            {"solution", f.solution},
            {"drive_matrix", MatrixJson(f.drive)},
            {"exposure", f.exposure},
            {"condition_number", f.condition},
            {"residual", f.residual},
            {"corners", corners},
            {"negative_share", double(f.negativeCorners) / double(f.corners.size())}};
        w["white_scores"] = ScoresJson(b.whiteScores);
        w["pre_correction"] = FitJson(b.preFit);
        w["pre_correction"]["matrix"] = MatrixJson(b.preCorrection);
        w["post_camera"] = FitJson(b.postFit);
        w["post_camera"]["matrix"] = MatrixJson(b.post);
        w["post_camera"]["root_polynomial"] = FitJson(b.postRootPolynomialFit);
        w["post_camera"]["root_polynomial"]["method"] = b.postMethod.name;
        w["post_camera"]["root_polynomial"]["degree"] = b.postRootPolynomial.degree();
        w["post_camera"]["root_polynomial"]["matrix"] = MatrixJson(b.postRootPolynomial.matrix());
        w["post_camera"]["registry_rootpoly_camera"] = StatisticsJson(b.postRegistry);
        w["out_of_frustum"] = Json::array();
        for (const WallShown& s : b.shown)
        {
            Json errors;
            for (const WallSetErrors& e : s.errors)
            {
                errors[e.set] = {{"before", StatisticsJson(e.before)},
                                 {"pre_corrected", StatisticsJson(e.preCorrected)},
                                 {"post_corrected", StatisticsJson(e.postCorrected)}};
            }
            w["out_of_frustum"].push_back({{"shows", s.light},
                                           {"drive", VectorJson(s.drive)},
                                           {"pre_corrected_drive", VectorJson(s.preDrive)},
                                           {"negative_drive", s.negative},
                                           {"errors", errors},
                                           {"scores", ScoresJson(s.scores)},
                                           {"pre_corrected_scores", ScoresJson(s.preScores)}});
        }
        j["white_balances"].push_back(w);
    }
    return j.dump(2);
}

std::string WallReport(const WallResult& r)
{
    std::ostringstream o;
    o << "wall: " << r.emitters.size() << " emitters (" << Emitters(r) << "), camera " << r.camera
      << ", content " << FindRgbSpace(r.contentSpace).displayName << ", plates "
      << FindRgbSpace(r.workingSpace).displayName << "\n";
    for (const WallBalance& b : r.balances)
    {
        const WallInFrustum& f = b.inFrustum;
        o << "\nwhite balance " << b.light << " (" << r.contextVariable << "=" << b.key << ", CCT "
          << Fixed(b.cct, 0) << " K)\n";
        o << "  in frustum: " << f.solution << " drive, condition number " << Fixed(f.condition, 2)
          << ", residual " << f.residual << ", exposure " << f.exposure << "\n";
        o << "    " << f.negativeCorners << " of " << f.corners.size()
          << " content corners need a negative drive";
        std::string negative;
        for (const WallCorner& c : f.corners)
        {
            negative += c.negative ? (negative.empty() ? ": " : ", ") + c.name : "";
        }
        o << negative << "\n";
        for (Eigen::Index e = 0; e < f.drive.rows(); ++e)
        {
            o << "    " << r.emitters[size_t(e)].name << " = " << Fixed(f.drive(e, 0), 6) << " R";
            for (Eigen::Index c = 1; c < 3; ++c)
            {
                o << (f.drive(e, c) < 0.0 ? " - " : " + ") << Fixed(std::abs(f.drive(e, c)), 6)
                  << (c == 1 ? " G" : " B");
            }
            o << "\n";
        }
        o << "  wall white: " << Headlines(b.whiteScores) << "\n";
        o << "  out of frustum, dE00 mean / p95 / max:\n";
        for (const WallShown& s : b.shown)
        {
            for (const WallSetErrors& e : s.errors)
            {
                o << "    shows " << s.light << ", " << e.set << ": before " << Stats(e.before)
                  << "; pre-corrected " << Stats(e.preCorrected) << "; post-camera "
                  << Stats(e.postCorrected) << (s.negative ? " (needs a negative drive)" : "")
                  << "\n";
            }
            o << "    the wall showing " << s.light << " as a light: " << Headlines(s.scores)
              << "; pre-corrected: " << Headlines(s.preScores) << "\n";
        }
        o << "  pre-correction (" << b.preFit.fit << ", over " << r.depicted.size() << " lights x "
          << r.trainingName << "): mean " << Fixed(b.preFit.before.mean, 2) << " -> "
          << Fixed(b.preFit.after.mean, 2) << " (plain least squares "
          << Fixed(b.preFit.leastSquares.mean, 2) << ")\n";
        o << "  post-camera 3x3 (" << b.postFit.fit << ", " << r.trainingName << "): mean "
          << Fixed(b.postFit.before.mean, 2) << " -> " << Fixed(b.postFit.after.mean, 2)
          << " (plain least squares " << Fixed(b.postFit.leastSquares.mean, 2)
          << "); root polynomial " << Fixed(b.postRootPolynomialFit.after.mean, 2) << " (plain "
          << Fixed(b.postRootPolynomialFit.leastSquares.mean, 2)
          << "); the registry's rootpoly-camera " << Fixed(b.postRegistry.mean, 2) << "\n";
    }
    return o.str();
}

WallDescriptions DescribeWallBalance(const WallResult& r, const WallBalance& b)
{
    std::ostringstream from;
    from << "Emitters " << Emitters(r) << "; camera " << r.camera << " white-balanced for "
         << b.light << " (CCT " << Fixed(b.cct, 0) << " K), read through bandlight's IDT for it to "
         << FindRgbSpace(r.workingSpace).displayName << "; training set " << r.trainingName << " ("
         << r.trainingCount << ").";
    WallDescriptions d;
    d.idt = "Raw camera RGB to " + FindRgbSpace(r.workingSpace).displayName +
            ": bandlight's IDT for " + b.light + ", gains folded in (rms dE*ab " +
            Fixed(b.idt.rmsDe76, 2) + " on the training set). " + from.str();
    std::ostringstream in;
    in << "In frustum: " << FindRgbSpace(r.contentSpace).displayName << " content to the drive of "
       << Emitters(r) << " (" << b.inFrustum.solution << " solution, condition number "
       << Fixed(b.inFrustum.condition, 2) << ", residual " << b.inFrustum.residual << "). "
       << from.str();
    d.inFrustum = in.str();
    std::ostringstream pre;
    pre << "Out of frustum: the lighting content's drive pre-corrected (" << r.emitters.size()
        << "x" << r.emitters.size() << ", fitted over " << r.depicted.size()
        << " depicted lights): dE00 mean " << Fixed(b.preFit.before.mean, 2) << " before, "
        << Fixed(b.preFit.after.mean, 2) << " after. " << from.str();
    d.preCorrection = pre.str();
    std::ostringstream post;
    post << "Post-camera: the plate of a scene lit by the wall showing " << b.light
         << " made to look as under " << b.light << ": dE00 mean "
         << Fixed(b.postFit.before.mean, 2) << " before, " << Fixed(b.postFit.after.mean, 2)
         << " after. " << from.str();
    d.postCamera = post.str();
    std::ostringstream rootpoly;
    rootpoly << "Post-camera, the method registry's " << b.postMethod.name
             << " op (a degree-2 root polynomial): the plate of a scene lit by the wall "
                "showing "
             << b.light << " made to look as under " << b.light << ": dE00 mean "
             << Fixed(b.postRootPolynomialFit.before.mean, 2) << " before, "
             << Fixed(b.postRootPolynomialFit.after.mean, 2) << " after (the root polynomial "
             << "itself, before its LUT). " << from.str();
    d.postRootPolynomial = rootpoly.str();
    return d;
}

std::string DescribeWallConfig(const WallResult& r)
{
    return "bandlight wall: an LED wall of " + std::to_string(r.emitters.size()) + " emitters (" +
           Emitters(r) + ") for camera " + r.camera + ", content " +
           FindRgbSpace(r.contentSpace).displayName + ". The context variable " +
           r.contextVariable +
           " selects the transforms of the camera's white balance. Generated by `bandlight wall`.";
}

}  // namespace bandlight::jobs
