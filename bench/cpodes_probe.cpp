// Counts what Simbody's CPodes integrator did in one run, for the Simbody models' speed
// study (bench/README.md, "Where the Simbody models' time goes"). Measurement only: not
// linked into rockroll. Simbody's CPodesIntegrator keeps its CPodes object private, so
// this library is preloaded and takes the CPodes object from the calls CPodesIntegrator
// makes through the dynamic linker (CPodes::step, CPodes::setNonlinConvCoef).
//
//   g++ -O2 -shared -fPIC -o build/libcpodes_probe.so bench/cpodes_probe.cpp -ldl
//   RR_CPODES_STATS=1 LD_PRELOAD=$PWD/build/libcpodes_probe.so build/bin/rockroll run scenarios/70ton-loaded.toml --model fullcar --out /tmp/probe --force
//
// prints at exit, for the last CPodes object that stepped: steps, right-hand sides of the
// Newton iterations, Jacobian evaluations and the right-hand sides they took (one per state
// for the finite-difference Jacobian), LU factorizations (linear-solver setups), Newton
// iterations, convergence and error-test failures.
// Experiments (they change results; see bench/README.md before using them):
//   RR_NLS_COEF=c    Newton convergence coefficient instead of Simbody's 0.01 (CPodes' own default is 0.1)
//   RR_NO_PROJ=1     do not register CPodes' projection (what Simbody patch 0003 does for systems
//                    without constraint equations; unsafe for systems with constraints)
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>

namespace {
void* gCpodes = nullptr;
struct Counts {
    int steps = 0, rhs = 0, linSetups = 0, errTestFails = 0, newtonIters = 0, convFails = 0, jacEvals = 0,
        jacRhs = 0;
};
Counts gLast;

int getCount(const char* symbol) {
    using Get = int (*)(void*, int*);
    int n = 0;
    if (auto f = reinterpret_cast<Get>(dlsym(RTLD_NEXT, symbol))) f(gCpodes, &n);
    return n;
}
void takeCounts() {
    Counts c;
    c.steps = getCount("_ZN5SimTK6CPodes11getNumStepsEPi");
    c.rhs = getCount("_ZN5SimTK6CPodes14getNumFctEvalsEPi");
    c.linSetups = getCount("_ZN5SimTK6CPodes19getNumLinSolvSetupsEPi");
    c.errTestFails = getCount("_ZN5SimTK6CPodes18getNumErrTestFailsEPi");
    c.newtonIters = getCount("_ZN5SimTK6CPodes21getNumNonlinSolvItersEPi");
    c.convFails = getCount("_ZN5SimTK6CPodes25getNumNonlinSolvConvFailsEPi");
    c.jacEvals = getCount("_ZN5SimTK6CPodes17dlsGetNumJacEvalsEPi");
    c.jacRhs = getCount("_ZN5SimTK6CPodes17dlsGetNumFctEvalsEPi");
    gLast = c;
}
struct Report {
    ~Report() {
        if (!std::getenv("RR_CPODES_STATS") || gLast.steps == 0) return;
        const Counts& c = gLast;
        std::fprintf(stderr,
                     "cpodes-probe: steps %d, Newton right-hand sides %d, Jacobian evaluations %d "
                     "(right-hand sides %d), LU factorizations %d, Newton iterations %d, "
                     "convergence failures %d, error-test failures %d\n",
                     c.steps, c.rhs, c.jacEvals, c.jacRhs, c.linSetups, c.newtonIters, c.convFails,
                     c.errTestFails);
    }
} gReport;
}  // namespace

// SimTK::CPodes::setNonlinConvCoef(double)
extern "C" int _ZN5SimTK6CPodes17setNonlinConvCoefEd(void* self, double coef) {
    using F = int (*)(void*, double);
    static const F real = reinterpret_cast<F>(dlsym(RTLD_NEXT, "_ZN5SimTK6CPodes17setNonlinConvCoefEd"));
    gCpodes = self;
    if (const char* e = std::getenv("RR_NLS_COEF")) coef = std::atof(e);
    return real(self, coef);
}

// SimTK::CPodes::step(double, double*, Vector&, Vector&, StepMode)
extern "C" int _ZN5SimTK6CPodes4stepEdPdRNS_7Vector_IdEES4_NS0_8StepModeE(void* self, double tout, double* tret,
                                                                          void* y, void* yp, int mode) {
    using F = int (*)(void*, double, double*, void*, void*, int);
    static const F real =
        reinterpret_cast<F>(dlsym(RTLD_NEXT, "_ZN5SimTK6CPodes4stepEdPdRNS_7Vector_IdEES4_NS0_8StepModeE"));
    gCpodes = self;
    const int r = real(self, tout, tret, y, yp, mode);
    takeCounts();
    return r;
}

// SimTK::CPodes::projDefine()
extern "C" int _ZN5SimTK6CPodes10projDefineEv(void* self) {
    using F = int (*)(void*);
    static const F real = reinterpret_cast<F>(dlsym(RTLD_NEXT, "_ZN5SimTK6CPodes10projDefineEv"));
    if (std::getenv("RR_NO_PROJ")) return 0;
    return real(self);
}
