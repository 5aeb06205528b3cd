// Slide 14's five properties as the readouts, the views' labels and `simulate` judge them
// (app/teaching/impact_report.h): a check mark only where the property holds.
#include <gtest/gtest.h>

#include "app/run/scene_source.h"
#include "app/run/simulation.h"
#include "app/teaching/impact_report.h"
#include "app/views/frame_builder.h"

namespace {

using app::Verdict;

physics::Params elastic() {
    physics::Params params;
    params.alpha = params.beta = params.mu = 1.0;
    params.epsilon = 0.0;
    return params;
}

// One step whose struck clusters had `before` J and `after` J, free of walls (1 kg m/s).
physics::ImpactProperties step(double before, double after, double momentumChange = 0.0) {
    physics::ImpactProperties p;
    p.contacts = p.struck = 2;
    p.kineticBefore = before;
    p.kineticAfter = after;
    p.momentumScale = 1.0;
    p.momentumChange = momentumChange;
    return p;
}

Verdict verdictOf(const app::ImpactRecord& record, const physics::Params& params, const char* name,
                  std::vector<physics::MirrorAsymmetry> mirrors = {}) {
    for (const app::PropertyVerdict& v : app::judgeProperties(record, mirrors, params)) {
        if (v.name == name) return v.verdict;
    }
    ADD_FAILURE() << "no property " << name;
    return Verdict::Untested;
}

}  // namespace

// Energy: more is broken, always; less is broken only where the contacts are elastic
// (the squeeze under the simultaneous solver loses all of it at beta = 1), kept with beta < 1.
TEST(ImpactReport, EnergyLostIsBrokenOnlyWhereTheContactsAreElastic) {
    app::ImpactRecord lost;
    lost.add(step(1.0, 0.0));
    EXPECT_EQ(verdictOf(lost, elastic(), "energy"), Verdict::Broken);
    physics::Params restitution = elastic();
    restitution.beta = 0.8;
    EXPECT_EQ(verdictOf(lost, restitution, "energy"), Verdict::Kept);
    physics::Params staticContacts = elastic();
    staticContacts.epsilon = 0.1;
    EXPECT_EQ(verdictOf(lost, staticContacts, "energy"), Verdict::Kept);
    app::ImpactRecord gained;
    gained.add(step(1.0, 1.75));
    EXPECT_EQ(verdictOf(gained, restitution, "energy"), Verdict::Broken);
    app::ImpactRecord kept;
    kept.add(step(1.0, 1.0));
    EXPECT_EQ(verdictOf(kept, elastic(), "energy"), Verdict::Kept);
    EXPECT_EQ(verdictOf(app::ImpactRecord{}, elastic(), "energy"), Verdict::Untested);
}

// Momentum beyond rounding is broken; symmetry needs the scene's mirrors; break-away is
// untested without a resting pair, broken when none parted; positivity counts what is left.
TEST(ImpactReport, EachPropertySaysWhatItMeasuredAndWhetherItHolds) {
    app::ImpactRecord record;
    record.add(step(1.0, 1.0, 1e-3));
    EXPECT_EQ(verdictOf(record, elastic(), "momentum"), Verdict::Broken);
    EXPECT_EQ(verdictOf(record, elastic(), "symmetry"), Verdict::Untested);
    EXPECT_EQ(verdictOf(record, elastic(), "symmetry", {{0.0, 0.0}}), Verdict::Kept);
    EXPECT_EQ(verdictOf(record, elastic(), "symmetry", {{0.0, 0.0}, {0.0, 0.43}}), Verdict::Broken);
    EXPECT_EQ(verdictOf(record, elastic(), "break-away"), Verdict::Untested);
    physics::ImpactProperties held = step(1.0, 1.0);
    held.restingPairs = 3;
    app::ImpactRecord lcp;
    lcp.add(held);
    EXPECT_EQ(verdictOf(lcp, elastic(), "break-away"), Verdict::Broken);
    held.brokeAway = 1;
    held.fastestApproachAfter = 0.5;
    app::ImpactRecord cradle;
    cradle.add(held);
    EXPECT_EQ(verdictOf(cradle, elastic(), "break-away"), Verdict::Kept);
    EXPECT_EQ(verdictOf(cradle, elastic(), "positivity"), Verdict::Broken);
    EXPECT_EQ(verdictOf(lcp, elastic(), "positivity"), Verdict::Kept);
    const std::string marks = app::propertiesMarks(app::judgeProperties(cradle, {}, elastic()));
    EXPECT_EQ(marks, "\u2713\u00a0momentum  \u2713\u00a0energy  \u2013\u00a0symmetry\n\u2713\u00a0break-away  \u2717\u00a0positivity");
    // A view's label explains its marks when the pointer rests on it (a student met
    // "positivity" and "break-away" nowhere else): each mark, its number and what it asks.
    const std::vector<app::PropertyVerdict> verdicts = app::judgeProperties(cradle, {}, elastic());
    const std::string tip = app::propertiesTooltip(verdicts);
    for (const app::PropertyVerdict& v : verdicts) {
        EXPECT_NE(tip.find(v.name + (v.value.empty() ? "" : ": " + v.value) + "\n" + v.meaning), std::string::npos) << v.name;
    }
    EXPECT_NE(tip.find("\u2717 positivity: fastest approach left 0.5 m/s"), std::string::npos) << tip;
}

// "Elastic" needs mu = 1 too: at epsilon = 0 a contact with no normal speed is static, and
// mu < 1 damps it (18 at mu = 0.5 kept 0.4 % of its energy and was marked broken).
// Positivity's slack is 1e-6 of a solver step's gravity: 07's 1.4e-9 m/s is rounding.
TEST(ImpactReport, ElasticNeedsMuOneAndPositivityAllowsRounding) {
    app::ImpactRecord lost;
    lost.add(step(1.0, 0.0039));
    physics::Params damped = elastic();
    damped.mu = 0.5;
    EXPECT_EQ(verdictOf(lost, damped, "energy"), Verdict::Kept);
    EXPECT_EQ(verdictOf(lost, elastic(), "energy"), Verdict::Broken);
    physics::Params slope;  // g = 9.81 m/s^2, h = 1/60 s, 4 substeps: slack 4.1e-8 m/s
    physics::ImpactProperties left = step(1.0, 0.5);
    left.fastestApproachAfter = 1.4e-9;
    app::ImpactRecord rounding;
    rounding.add(left);
    EXPECT_EQ(verdictOf(rounding, slope, "positivity"), Verdict::Kept);
    left.fastestApproachAfter = 5e-8;
    app::ImpactRecord approaching;
    approaching.add(left);
    EXPECT_EQ(verdictOf(approaching, slope, "positivity"), Verdict::Broken);
}

// The contacts' properties are measured around a step's K passes; the continuous method
// meets its impacts one at a time within the step, and says so instead of a dash alone
// (15's view B showed "- momentum - energy" beside a text about its kept energy). The
// symmetry is the state's, measured under every method.
TEST(ImpactReport, TheContinuousMethodSaysItsContactsAreNotMeasured) {
    physics::Params continuous = elastic();
    continuous.method = physics::Method::Continuous;
    app::ImpactRecord record;
    record.add(step(1.0, 1.0));
    for (const app::PropertyVerdict& v : app::judgeProperties(record, {{0.0, 0.0}}, continuous)) {
        if (v.name == "symmetry") {
            EXPECT_EQ(v.verdict, Verdict::Kept);
            continue;
        }
        EXPECT_EQ(v.verdict, Verdict::Untested) << v.name;
        EXPECT_EQ(v.value, "not measured under the continuous method") << v.name;
    }
    // A view's label under the continuous method with no mirror plane: not "none tested yet",
    // which a student read still at 13 s.
    EXPECT_EQ(app::propertiesMarks(app::judgeProperties(record, {}, continuous)),
              "properties: not measured under the continuous method");
    EXPECT_EQ(app::propertiesMarks(app::judgeProperties(app::ImpactRecord{}, {}, elastic())), "properties: none tested yet");
}

// The readouts show the five properties under the continuous method too, each saying it is
// not measured (the 20th audit found the section missing: no contact was ever measured).
TEST(ImpactReport, TheReadoutsSayTheContinuousMethodMeasuresNoContact) {
    app::Simulation simulation(app::loadSceneWithSettings("16_bernoulli", {"method=continuous"}));
    for (int k = 0; k < 3; ++k) simulation.singleStep();
    const ui::Readouts readouts = app::makeReadouts(simulation, ui::FrameTimes{});
    ASSERT_EQ(readouts.properties.size(), 5u);
    EXPECT_EQ(readouts.properties[0].name, "momentum");
    EXPECT_EQ(readouts.properties[0].value, "not measured under the continuous method");
}
