#include "bespoke/StiffIntegrator.h"

#include <cvodes/cvodes.h>  // CVODES: CVODE plus quadratures (same BDF integrator)
#include <fmt/format.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>

namespace rockroll {

struct StiffIntegrator::Impl {
    SUNContext ctx = nullptr;
    N_Vector y = nullptr, absTol = nullptr, q = nullptr;
    bool quadInitialized = false;
    const StiffIntegrator::Rhs* rhs = nullptr;   // CVODE's user data is this Impl
    const StiffIntegrator::Rhs* quad = nullptr;
    SUNMatrix A = nullptr;
    SUNLinearSolver LS = nullptr;
    void* mem = nullptr;
    std::string lastError;
};

namespace {
int cvodeRhs(sunrealtype t, N_Vector y, N_Vector yDot, void* impl) {
    const auto* rhs = static_cast<StiffIntegrator::Impl*>(impl)->rhs;
    (*rhs)(t, N_VGetArrayPointer(y), N_VGetArrayPointer(yDot));
    for (sunindextype i = 0; i < N_VGetLength(yDot); ++i)
        if (!std::isfinite(N_VGetArrayPointer(yDot)[i])) return 1;  // recoverable: CVODE cuts the step
    return 0;
}

int cvodeQuadRhs(sunrealtype t, N_Vector y, N_Vector qDot, void* impl) {
    const auto* g = static_cast<StiffIntegrator::Impl*>(impl)->quad;
    (*g)(t, N_VGetArrayPointer(y), N_VGetArrayPointer(qDot));
    for (sunindextype i = 0; i < N_VGetLength(qDot); ++i)
        if (!std::isfinite(N_VGetArrayPointer(qDot)[i])) return 1;
    return 0;
}

void cvodeError(int code, const char* module, const char* function, char* msg, void* impl) {
    static_cast<StiffIntegrator::Impl*>(impl)->lastError = fmt::format("{} {} ({}): {}", module, function, code, msg);
}
}  // namespace

StiffIntegrator::StiffIntegrator(int n, Rhs rhs, double relTol, std::vector<double> absTol)
    : impl_(std::make_unique<Impl>()), n_(n), rhs_(std::move(rhs)), y_(n, 0.0) {
    if (int(absTol.size()) != n) throw std::invalid_argument("StiffIntegrator: one absolute tolerance per state");
    Impl& m = *impl_;
    SUNContext_Create(nullptr, &m.ctx);
    m.y = N_VNew_Serial(n, m.ctx);
    m.absTol = N_VNew_Serial(n, m.ctx);
    for (int i = 0; i < n; ++i) NV_Ith_S(m.absTol, i) = absTol[i];
    m.mem = CVodeCreate(CV_BDF, m.ctx);
    CVodeInit(m.mem, cvodeRhs, 0.0, m.y);
    CVodeSVtolerances(m.mem, relTol, m.absTol);
    m.rhs = &rhs_;
    CVodeSetUserData(m.mem, &m);
    CVodeSetErrHandlerFn(m.mem, cvodeError, &m);
    m.A = SUNDenseMatrix(n, n, m.ctx);
    m.LS = SUNLinSol_Dense(m.y, m.A, m.ctx);
    CVodeSetLinearSolver(m.mem, m.LS, m.A);
    CVodeSetMaxNumSteps(m.mem, 1000000);
}

StiffIntegrator::~StiffIntegrator() {
    Impl& m = *impl_;
    CVodeFree(&m.mem);
    SUNLinSolFree(m.LS);
    SUNMatDestroy(m.A);
    N_VDestroy(m.absTol);
    if (m.q) N_VDestroy(m.q);
    N_VDestroy(m.y);
    SUNContext_Free(&m.ctx);
}

void StiffIntegrator::setQuadrature(int nq, Rhs g) {
    Impl& m = *impl_;
    if (m.q) throw std::logic_error("StiffIntegrator: quadrature already set");
    quadRhs_ = std::move(g);
    m.quad = &quadRhs_;
    m.q = N_VNew_Serial(nq, m.ctx);
    q_.assign(nq, 0.0);
}

void StiffIntegrator::initialize(double t0, const double* y0) {
    for (int i = 0; i < n_; ++i) NV_Ith_S(impl_->y, i) = y0[i];
    CVodeReInit(impl_->mem, t0, impl_->y);
    if (impl_->q) {
        N_VConst(0.0, impl_->q);
        if (impl_->quadInitialized) CVodeQuadReInit(impl_->mem, impl_->q);
        else CVodeQuadInit(impl_->mem, cvodeQuadRhs, impl_->q);
        impl_->quadInitialized = true;  // errconQ stays off: q is not in the error test
        q_.assign(q_.size(), 0.0);
    }
    t_ = t0;
    y_.assign(y0, y0 + n_);
}

void StiffIntegrator::advanceTo(double tOut) {
    sunrealtype tReached = t_;
    const int flag = CVode(impl_->mem, tOut, impl_->y, &tReached, CV_NORMAL);
    if (flag < 0) {
        // The state CVODE holds is the last successful step's.
        CVodeGetCurrentTime(impl_->mem, &tReached);
        throw NumericalFailure(fmt::format("CVODE BDF failed near t = {:.6f} s: {}\nlast good state:\n{}",
                                             double(tReached), impl_->lastError, describeState()),
                                 double(tReached));
    }
    t_ = tReached;
    for (int i = 0; i < n_; ++i) y_[i] = NV_Ith_S(impl_->y, i);
    if (impl_->q) {
        sunrealtype tq = tReached;
        CVodeGetQuad(impl_->mem, &tq, impl_->q);  // interpolated to tReached like y
        for (size_t i = 0; i < q_.size(); ++i) q_[i] = NV_Ith_S(impl_->q, i);
    }
}

long StiffIntegrator::getNumSteps() const {
    long n = 0;
    CVodeGetNumSteps(impl_->mem, &n);
    return n;
}

long StiffIntegrator::getNumRhsEvaluations() const {
    long nf = 0, nfLs = 0;
    CVodeGetNumRhsEvals(impl_->mem, &nf);
    CVodeGetNumLinRhsEvals(impl_->mem, &nfLs);
    return nf + nfLs;
}

std::string StiffIntegrator::describeState() const {
    std::string out;
    for (int i = 0; i < n_; ++i)
        out += fmt::format("  {:<16} {: .9e}\n", i < int(names_.size()) ? names_[i] : fmt::format("y[{}]", i),
                           NV_Ith_S(impl_->y, i));
    return out;
}

}  // namespace rockroll
