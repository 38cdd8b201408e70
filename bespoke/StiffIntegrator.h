#pragma once
// Variable-step, variable-order BDF integration of y' = f(t, y) for the
// hand-written models, on SUNDIALS CVODE (Debian's libsundials-dev) with a dense
// direct linear solver and a difference-quotient Jacobian. BDF copes with the
// stiff contacts and bristle friction; explicit Runge–Kutta does not.
#include "mbmodel/TimeHistory.h"

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockroll {


class StiffIntegrator {
public:
    using Rhs = std::function<void(double t, const double* y, double* yDot)>;

    /// relTol: relative tolerance; absTol: absolute tolerance per component.
    StiffIntegrator(int n, Rhs rhs, double relTol, std::vector<double> absTol);
    ~StiffIntegrator();
    StiffIntegrator(const StiffIntegrator&) = delete;
    StiffIntegrator& operator=(const StiffIntegrator&) = delete;

    /// Optional quadratures q' = g(t, y), integrated by CVODE alongside y with
    /// the same steps but outside its error control (CVodeQuadInit, errconQ
    /// off), e.g. the energy audit's work integrals. Call before initialize();
    /// initialize() starts them at 0.
    void setQuadrature(int nq, Rhs g);
    /// q at getTime() (interpolated with the state at output times).
    const std::vector<double>& getQuadrature() const { return q_; }

    void initialize(double t0, const double* y0);
    /// Integrates to tOut (interpolated output); throws NumericalFailure (mbmodel/TimeHistory.h).
    void advanceTo(double tOut);
    double getTime() const { return t_; }
    const std::vector<double>& getState() const { return y_; }
    long getNumSteps() const;
    long getNumRhsEvaluations() const;
    void setStateNames(std::vector<std::string> names) { names_ = std::move(names); }

    struct Impl;  ///< CVODE's objects

private:
    std::string describeState() const;

    std::unique_ptr<Impl> impl_;
    int n_;
    Rhs rhs_;
    Rhs quadRhs_;
    double t_ = 0;
    std::vector<double> y_, q_;
    std::vector<std::string> names_;
};

}  // namespace rockroll
