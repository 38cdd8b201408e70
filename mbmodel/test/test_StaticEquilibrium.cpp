// Both Simbody models start in static equilibrium with every load equal to its
// weight share, for each of the report's cars.
#include "mbmodel/RockingModel.h"
#include "scenarios/ScenarioLoader.h"
#include "scenarios/ModelRegistry.h"

#include <gtest/gtest.h>

#include <cctype>
#include <ostream>
#include <string>

using namespace rockroll;

namespace {
struct Case {
    std::string model, car;
};
// How gtest prints a parameter (test listings, failures): the names, not the struct's bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.model << " " << c.car; }
class StaticEquilibrium : public ::testing::TestWithParam<Case> {};

double channel(const RockingModel& m, const std::vector<double>& v, const std::string& name) {
    const int i = m.getChannels().find(name);
    EXPECT_GE(i, 0) << name;
    return i >= 0 ? v[i] : 0;
}
}  // namespace

TEST_P(StaticEquilibrium, AccelerationsVanishAndLoadsEqualWeightShares) {
    const CarParameters car = makeCarParameters(GetParam().car);
    TrackSpec track;
    track.amplitude = 0.75 * units::inch;
    const auto model = ModelRegistry::get().getModel(GetParam().model).makeMultibody(
        car, TrackInput(track), ModelOptions{16.5 * units::mph, TrackEntry::Lead, TrackMotion{}, AttributionSwitches{}, WheelRailSettings{}, CarBodySettings{}});
    const SimTK::State s = model->makeStaticState();
    model->getSystem().realize(s, SimTK::Stage::Acceleration);
    const SimTK::Vector& udot = s.getUDot();
    for (int i = 0; i < udot.size(); ++i) EXPECT_NEAR(udot[i], 0.0, 1e-6) << "mobility " << i;

    std::vector<double> v;
    model->calcChannels(s, v);
    const double lb = units::lbf;
    const double carBodyPerTruck = car.getCarBodyWeight() / 2 / lb;
    const double springShare = (carBodyPerTruck + car.bolsterWeight / lb) / 2;
    const double truckSideWheels = springShare + (car.wheelsetWeight + car.sideFrameWeight) / lb;
    double totalWheels = 0;
    for (int t = 0; t < model->getNumTrucks(); ++t) {
        const std::string T = t == 0 ? "F" : "R";
        EXPECT_NEAR(channel(*model, v, "center_plate_" + T + "_lb"), carBodyPerTruck, 1e-6 * carBodyPerTruck);
        for (const char* S : {"L", "R"}) {
            EXPECT_NEAR(channel(*model, v, "spring_" + T + "_" + S + "_lb"), springShare, 1e-6 * springShare);
            EXPECT_NEAR(channel(*model, v, "wheels_" + T + "_" + S + "_lb"), truckSideWheels, 1e-6 * truckSideWheels);
            EXPECT_EQ(channel(*model, v, "side_bearing_" + T + "_" + S + "_lb"), 0.0);
            EXPECT_EQ(channel(*model, v, "wedge_vertical_" + T + "_" + S + "_lb"), 0.0);
            totalWheels += channel(*model, v, "wheels_" + T + "_" + S + "_lb");
        }
    }
    // The wheels carry the whole car (the half car: half of it).
    const double share = model->getNumTrucks() == 2 ? 1.0 : 0.5;
    const double total = (car.bodyAndBolstersWeight + 4 * (car.wheelsetWeight + car.sideFrameWeight)) / lb;
    EXPECT_NEAR(totalWheels, share * total, 1e-6 * total);
    EXPECT_EQ(channel(*model, v, "roll_deg"), 0.0);
}

// The full car's Free car body carries its orientation as angles, so the state has no
// constraint equation: nothing for CPodes to project after a step (patch 0003 then
// registers no projection; bench/README.md, "Euler angles for the full car's body").
TEST_P(StaticEquilibrium, NoOrientationIsAQuaternionSoNothingIsProjected) {
    const CarParameters car = makeCarParameters(GetParam().car);
    const auto model = ModelRegistry::get().getModel(GetParam().model).makeMultibody(
        car, TrackInput(TrackSpec{}), ModelOptions{16.5 * units::mph, TrackEntry::Lead, TrackMotion{}, AttributionSwitches{}, WheelRailSettings{}, CarBodySettings{}});
    for (const SimTK::State& s : {model->makeDefaultState(), model->makeStaticState()}) {
        model->getSystem().realize(s, SimTK::Stage::Acceleration);
        EXPECT_TRUE(model->getMatter().getUseEulerAngles(s));
        EXPECT_EQ(model->getMatter().getNumQuaternionsInUse(s), 0);
        EXPECT_EQ(s.getNYErr(), 0);
        EXPECT_EQ(model->getCarBody().getNumQ(s), model->getCarBody().getNumU(s));
    }
}

INSTANTIATE_TEST_SUITE_P(AllCars, StaticEquilibrium,
                         ::testing::Values(Case{"halfcar", "70ton-loaded"}, Case{"fullcar", "70ton-loaded"},
                                           Case{"halfcar", "70ton-empty"}, Case{"fullcar", "70ton-empty"},
                                           Case{"halfcar", "100ton-loaded"}, Case{"fullcar", "100ton-loaded"}),
                         [](const auto& info) {
                             std::string n = info.param.model + "_" + info.param.car;
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });
