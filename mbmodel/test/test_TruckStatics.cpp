// The truck's static equilibrium is defined once (mbmodel/TruckStatics.h). Every
// formulation — the Simbody half and full car, the equations-of-motion half car, the
// describing function (through its static guess) and the reduced model's massless
// truck — must carry exactly its loads in its own static state, each computing the
// loads from its own kinematics and element laws.
#include "bespoke/DescribingFunction.h"
#include "bespoke/EomHalfCarModel.h"
#include "bespoke/ReducedHalfCarModel.h"
#include "contacts/SpringGroupLaws.h"
#include "mbmodel/RockingModel.h"
#include "mbmodel/TruckStatics.h"
#include "scenarios/ModelRegistry.h"
#include "scenarios/ScenarioLoader.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rockroll;

namespace {
constexpr double kRel = 1e-9;
const char* const kCars[] = {"70ton-loaded", "70ton-empty", "100ton-loaded"};

void expectRel(double actual, double expected, const std::string& what) {
    EXPECT_NEAR(actual, expected, kRel * std::abs(expected)) << what;
}

TruckStatics makeStatics(const CarParameters& car, TruckWeight weight = TruckWeight::Carried) {
    TruckStaticLoad load;
    load.carBody = car.getCarBodyWeight() / 2;
    load.weight = weight;
    return TruckStatics(car, load);
}

double channel(const RockingModel& m, const std::vector<double>& v, const std::string& name) {
    const int i = m.getChannels().find(name);
    EXPECT_GE(i, 0) << name;
    return i >= 0 ? v[i] : NAN;
}
}  // namespace

TEST(TruckStatics, LoadsBalanceTheWeightsAndTheSpringLawGivesItsLoad) {
    for (const char* name : kCars) {
        const CarParameters car = makeCarParameters(name);
        const TruckStatics t = makeStatics(car);
        const double Q = car.getCarBodyWeight() / 2;
        EXPECT_EQ(t.getCenterPlateLoad(), Q);
        // The two spring groups carry the car body and the bolster; the rails carry
        // that and the unsprung weight of both wheelsets.
        expectRel(2 * t.getSpringLoad(), Q + car.bolsterWeight, name);
        expectRel(2 * t.getTruckSideWheelLoad(), Q + car.bolsterWeight + 2 * (car.wheelsetWeight + car.sideFrameWeight),
                  name);
        const VerticalSpringLaw law{car.springVerticalRate, car.springTravel, car.bottomingRate};
        expectRel(calcVerticalSpringForce(t.getSpringCompression(), law), t.getSpringLoad(), name);
        // Two separate wheelsets carry, between them, what one lumped one carries.
        expectRel(2 * t.calcWheelLoad(1, 2), t.calcWheelLoad(2, 1), name);
        expectRel(t.calcWheelDeflection(1, 2), t.calcWheelDeflection(2, 1), name);
        expectRel(t.calcWheelDeflection(2, 1) * 2 * car.contactStiffnessScale * car.wheelRailStiffness,
                  t.getTruckSideWheelLoad(), name);

        const TruckStatics massless = makeStatics(car, TruckWeight::Massless);
        expectRel(2 * massless.getSpringLoad(), Q, name);
        expectRel(massless.getTruckSideWheelLoad(), massless.getSpringLoad(), name);
    }
}

TEST(TruckStatics, SimbodyHalfAndFullCarCarryTheStaticLoads) {
    for (const char* name : kCars)
        for (const char* model : {"halfcar", "fullcar"}) {
            const std::string what = std::string(model) + " " + name;
            const CarParameters car = makeCarParameters(name);
            const TruckStatics t = makeStatics(car);
            const auto m = ModelRegistry::get().getModel(model).makeMultibody(
                car, TrackInput(TrackSpec{}), ModelOptions{16.5 * units::mph, TrackEntry::Lead, TrackMotion{}, {}, {}, {}});
            const SimTK::State s = m->makeStaticState();
            m->getSystem().realize(s, SimTK::Stage::Acceleration);
            std::vector<double> v;
            m->calcChannels(s, v);
            const double lb = units::lbf;
            for (int k = 0; k < m->getNumTrucks(); ++k) {
                const std::string T = k == 0 ? "F" : "R";
                const Truck& truck = m->getTruck(k);
                expectRel(channel(*m, v, "center_plate_" + T + "_lb") * lb, t.getCenterPlateLoad(), what + " plate");
                for (const char* S : {"L", "R"}) {
                    expectRel(channel(*m, v, "spring_" + T + "_" + S + "_lb") * lb, t.getSpringLoad(), what + " spring");
                    expectRel(channel(*m, v, "wheels_" + T + "_" + S + "_lb") * lb, t.getTruckSideWheelLoad(),
                              what + " wheels");
                    EXPECT_EQ(channel(*m, v, "side_bearing_" + T + "_" + S + "_lb"), 0.0) << what;
                }
                for (int side : {0, 1})
                    expectRel(truck.getVerticalSpring(side).calcCompression(s), t.getSpringCompression(),
                              what + " compression");
                for (int i = 0; i < truck.getNumWheelsets(); ++i)
                    expectRel(truck.calcStaticWheelLoad(i),
                              t.calcWheelLoad(truck.getNumWheelsets() == 1 ? 2 : 1, truck.getNumWheelsets()),
                              what + " wheelset");
            }
        }
}

TEST(TruckStatics, EquationsOfMotionHalfCarAndDescribingFunctionCarryTheStaticLoads) {
    for (const char* name : kCars) {
        const CarParameters car = makeCarParameters(name);
        const TruckStatics t = makeStatics(car);
        const EomHalfCarModel eom(car, [](double) { return RailState{}; });
        const EomHalfCarModel::Forces f = eom.calcForces(0, eom.makeStaticState());
        expectRel(f.rim[0] + f.rim[1], t.getCenterPlateLoad(), name);
        for (int side : {0, 1}) {
            expectRel(f.spring[side], t.getSpringLoad(), name);
            expectRel(f.wheel[side], t.getTruckSideWheelLoad(), name);
            EXPECT_EQ(f.sideBearing[side], 0.0) << name;
        }
        // The describing function's element harmonics, evaluated at its static guess
        // with no input, give the same constant loads.
        const DescribingFunctionModel df(car, 0.0, 39 * units::foot);
        const SteadyStatePoint p = df.describe(df.makeStaticGuess(), 15);
        expectRel(p.wheelLoad.meanLb * units::lbf, t.getTruckSideWheelLoad(), name);
        expectRel(p.centerPlateLoad.meanLb * units::lbf, t.getCenterPlateLoad(), name);
        EXPECT_EQ(p.sideBearingLoad.meanLb, 0.0) << name;
        // No input, no harmonics.
        EXPECT_LT(p.wheelLoad.firstLb + p.wheelLoad.secondLb, 1e-6 * p.wheelLoad.meanLb) << name;
        EXPECT_LT(p.centerPlateLoad.firstLb + p.centerPlateLoad.secondLb, 1e-6 * p.centerPlateLoad.meanLb) << name;
    }
}

TEST(TruckStatics, ReducedModelsTruckEquilibriumCarriesTheStaticLoads) {
    for (const char* name : kCars)
        for (bool truckWeight : {false, true}) {
            const std::string what = std::string(name) + (truckWeight ? " with truck weight" : " massless");
            const CarParameters car = makeCarParameters(name);
            const TruckStatics t = makeStatics(car, truckWeight ? TruckWeight::Carried : TruckWeight::Massless);
            const ReducedHalfCarModel m(car, [](double) { return RailState{}; }, ReducedOptions{truckWeight});
            const auto e = m.evaluate(0, m.makeStaticState(), m.makeStaticMemory());
            ASSERT_TRUE(e.truck.consistent) << what;
            expectRel(e.truck.rim[0] + e.truck.rim[1], t.getCenterPlateLoad(), what);
            for (int side : {0, 1}) {
                expectRel(e.truck.spring[side], t.getSpringLoad(), what);
                expectRel(e.truck.wheel[side], t.getTruckSideWheelLoad(), what);
                expectRel(e.truck.compression[side], t.getSpringCompression(), what);
                EXPECT_EQ(e.truck.sideBearing[side], 0.0) << what;
            }
            expectRel(m.calcStaticWheelLoad(), t.getTruckSideWheelLoad(), what);
        }
}

// The same deflection gives the same force in every formulation: the spring groups
// of the Simbody half car and of the equations-of-motion half car, with the bolster
// pushed down by 1 in from static, for each of the three cars.
TEST(TruckStatics, SameDeflectionGivesTheSameSpringForceInEveryFormulation) {
    for (const char* name : kCars) {
        const CarParameters car = makeCarParameters(name);
        const VerticalSpringLaw law{car.springVerticalRate, car.springTravel, car.bottomingRate};
        const double dz = -1.0 * units::inch;

        const auto m = ModelRegistry::get().getModel("halfcar").makeMultibody(
            car, TrackInput(TrackSpec{}), ModelOptions{16.5 * units::mph, TrackEntry::Lead, TrackMotion{}, {}, {}, {}});
        SimTK::State s = m->makeStaticState();
        const SimTK::MobilizedBody& bolster = m->getTruck(0).getBolster();
        bolster.setOneQ(s, 2, bolster.getOneQ(s, 2) + dz);
        m->getSystem().realize(s, SimTK::Stage::Dynamics);
        const double zSimbody = m->getTruck(0).getVerticalSpring(0).calcCompression(s);

        const EomHalfCarModel eom(car, [](double) { return RailState{}; });
        EomHalfCarModel::State y = eom.makeStaticState();
        y[3 * EomHalfCarModel::Bolster + 2] += dz;
        const EomHalfCarModel::Forces f = eom.calcForces(0, y);

        const double Z = makeStatics(car).getSpringCompression() - dz;
        expectRel(zSimbody, Z, name);
        for (int side : {0, 1}) {
            expectRel(m->getTruck(0).getVerticalSpring(side).calcForce(s), calcVerticalSpringForce(Z, law), name);
            expectRel(f.spring[side], calcVerticalSpringForce(Z, law), name);
        }
    }
}
