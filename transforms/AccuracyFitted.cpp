// SPDX-License-Identifier: BSD-3-Clause
// The measures of methods fitted on the very colours they are judged on:
// CrossValidate (each fitted method in-sample and N-fold cross-validated on
// its training set) and MeasureFloor (the best 3x3 and root polynomial for
// each set).
#include "transforms/Accuracy.h"

#include "transforms/RootPolynomial.h"
#include "transforms/detail/AccuracyParts.h"

namespace bandlight
{

namespace
{

using detail::ForEachPair;
using detail::LitJudge;
using detail::MakePairPlates;
using detail::MakeRow;
using detail::PairPlates;
using detail::Score;
using detail::WithPlates;

}  // namespace

std::string InSampleSetName()
{
    return "training, in-sample";
}

std::string CrossValidatedSetName(int folds)
{
    return "training, " + std::to_string(folds) + "-fold";
}

const std::vector<std::string>& FloorMethodNames()
{
    static const std::vector<std::string> names = {"floor-3x3", "floor-rootpoly"};
    return names;
}

std::vector<AccuracyRow> CrossValidate(const AccuracyOptions& o, int folds)
{
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    std::vector<MethodSpec> methods;
    for (const std::string& m : o.methods)
    {
        const MethodSpec spec = ParseMethod(m);
        if (spec.entry().takesTraining)
        {
            methods.push_back(spec);
        }
    }
    if (methods.empty() || folds < 2)
    {
        return {};
    }
    const std::string inSample = InSampleSetName();
    const std::string crossName = CrossValidatedSetName(folds);
    return ForEachPair(
        o, {},
        [&](const Light& from, const Light& to, std::vector<AccuracyRow>& rows)
        {
            const SurfaceRenderer r1(from.spectrum, working, o.observer);
            const SurfaceRenderer r2(to.spectrum, working, o.observer);
            for (const Plates& plates : o.plates)
            {
                const PairPlates pp = MakePairPlates(plates, from, to, r2, working, o.observer);
                for (const MethodSpec& parsed : methods)
                {
                    const MethodSpec method = WithPlates(parsed, plates, o);
                    const std::vector<NamedSpectrum>& all = TrainingOf(method);
                    const auto evaluate = [&](const MethodSpec& fitted,
                                              const std::vector<NamedSpectrum>& test,
                                              std::vector<Vec3>& predicted, std::vector<Vec3>& ref)
                    {
                        const Relighter relight(from, to, fitted, working, o.observer);
                        for (const NamedSpectrum& t : test)
                        {
                            const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
                            predicted.push_back(relight.apply(pp.balanceFrom * r1.render(r)));
                            ref.push_back(pp.balanceTo * r2.render(r));
                        }
                    };
                    {
                        MethodSpec fitted = method;
                        fitted.training = all;
                        std::vector<Vec3> predicted, ref;
                        evaluate(fitted, all, predicted, ref);
                        rows.push_back(MakeRow(method.name, from, to, inSample, 1.0, false,
                                               Score(pp.judge, predicted, ref, all), plates.key()));
                    }
                    // Folds by position (every folds-th sample), the same for every pair.
                    std::vector<Vec3> predicted, ref;
                    std::vector<NamedSpectrum> order;
                    for (int f = 0; f < folds; ++f)
                    {
                        MethodSpec fitted = method;
                        std::vector<NamedSpectrum> test;
                        for (size_t i = 0; i < all.size(); ++i)
                        {
                            (int(i % size_t(folds)) == f ? test : fitted.training)
                                .push_back(all[i]);
                        }
                        evaluate(fitted, test, predicted, ref);
                        order.insert(order.end(), test.begin(), test.end());
                    }
                    rows.push_back(MakeRow(method.name, from, to, crossName, 1.0, false,
                                           Score(pp.judge, predicted, ref, order), plates.key()));
                }
            }
        });
}

std::vector<AccuracyRow> MeasureFloor(const AccuracyOptions& o)
{
    const RgbSpace& working = FindRgbSpace(o.workingSpace);
    return ForEachPair(
        o, {},
        [&](const Light& from, const Light& to, std::vector<AccuracyRow>& rows)
        {
            const SurfaceRenderer r1(from.spectrum, working, o.observer);
            const SurfaceRenderer r2(to.spectrum, working, o.observer);
            for (const ReflectanceSet& set : o.sets)
            {
                const Mat3 m = FitLabMatrix(r1, r2, set.samples);
                const RootPolynomial rp = FitRootPolynomial(r1, r2, set.samples, 2);
                std::vector<Vec3> by3x3, byRoot, ref;
                for (const NamedSpectrum& t : set.samples)
                {
                    const SurfaceRenderer::Samples r = SurfaceRenderer::Sample(t.spectrum);
                    by3x3.push_back(m * r1.render(r));
                    byRoot.push_back(rp.apply(r1.render(r)));
                    ref.push_back(r2.render(r));
                }
                rows.push_back(MakeRow(FloorMethodNames()[0], from, to, set.name, 1.0, false,
                                       Score(LitJudge(r2), by3x3, ref, set.samples)));
                rows.push_back(MakeRow(FloorMethodNames()[1], from, to, set.name, 1.0, false,
                                       Score(LitJudge(r2), byRoot, ref, set.samples)));
            }
        });
}

}  // namespace bandlight
