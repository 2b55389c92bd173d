// dopri5: ARKODE's explicit Runge-Kutta stepper (ERKStep) with the Dormand-Prince 5(4)
// table: seven stages, first-same-as-last, fifth-order solution with an embedded fourth-order
// error estimate. Dense output is cubic Hermite (degree 3), which needs no extra evaluations;
// ARKODE's quartic and quintic interpolants would evaluate f again at every output and at
// every root-finding probe.
#include <arkode/arkode_erkstep.h>

#include "core/sundials_integrators.hpp"
#include "core/sundials_stepper.hpp"

namespace tribo {

namespace {

class ArkodeDopri5 final : public SundialsStepper {
 public:
  explicit ArkodeDopri5(const Model& model) : SundialsStepper(model, "dopri5") {}
  ~ArkodeDopri5() override {
    if (memory_) ERKStepFree(&memory_);
    if (error_) N_VDestroy(error_);
    if (weight_) N_VDestroy(weight_);
  }

 private:
  void start(double t0, double initial_step) override {
    if (memory_) {
      if (ERKStepReInit(memory_, rhsCallback, t0, y_) != ARK_SUCCESS ||
          ERKStepSetInitStep(memory_, initial_step) != ARK_SUCCESS)
        fail("ERKStepReInit failed");
      return;
    }
    memory_ = ERKStepCreate(rhsCallback, t0, y_, context_);
    if (!memory_) return fail("cannot create the ARKODE ERKStep solver");
    error_ = N_VClone(y_);
    weight_ = N_VClone(y_);
    bool ok = error_ && weight_;
    ok = ok && ERKStepSetErrHandlerFn(memory_, errorCallback, this) == ARK_SUCCESS;
    ok = ok && ERKStepSetUserData(memory_, this) == ARK_SUCCESS;
    ok = ok && ERKStepSetTableNum(memory_, ARKODE_DORMAND_PRINCE_7_4_5) == ARK_SUCCESS;
    ok = ok && ERKStepSStolerances(memory_, options_.relative_tolerance,
                                   options_.absolute_tolerance) == ARK_SUCCESS;
    ok = ok && ERKStepSetInterpolantDegree(memory_, 3) == ARK_SUCCESS;
    if (options_.max_internal_step > 0.0)
      ok = ok && ERKStepSetMaxStep(memory_, options_.max_internal_step) == ARK_SUCCESS;
    if (system_.eventCount() > 0) {
      ok = ok && ERKStepRootInit(memory_, system_.eventCount(), rootCallback) == ARK_SUCCESS;
      ok = ok && ERKStepSetNoInactiveRootWarn(memory_) == ARK_SUCCESS;
    }
    if (!ok) fail("setting up ARKODE failed");
  }

  void discard() override {
    if (memory_) ERKStepFree(&memory_);
    if (error_) N_VDestroy(error_);
    if (weight_) N_VDestroy(weight_);
    memory_ = nullptr;
    error_ = weight_ = nullptr;
  }

  Advance advance(double tout, double stop, double& t) override {
    if (stop != kNoStop && ERKStepSetStopTime(memory_, stop) != ARK_SUCCESS) {
      last_flag_ = ARK_ILL_INPUT;
      if (last_error_.empty()) last_error_ = "ERKStepSetStopTime failed";
      return Advance::kFailed;
    }
    last_flag_ = ERKStepEvolve(memory_, tout, y_, &t, ARK_NORMAL);
    if (last_flag_ == ARK_SUCCESS) return Advance::kReached;
    if (last_flag_ == ARK_TSTOP_RETURN) return Advance::kStop;
    if (last_flag_ == ARK_ROOT_RETURN) return Advance::kRoot;
    if (last_error_.empty()) last_error_ = ERKStepGetReturnFlagName(last_flag_);
    return Advance::kFailed;
  }

  void setMaxSteps(long steps) override {
    if (memory_) ERKStepSetMaxNumSteps(memory_, steps);
  }

  double lastStep() override {
    double h = 0.0;
    if (memory_) ERKStepGetLastStep(memory_, &h);
    return h;
  }

  Stats statistics() override {
    Stats s;
    if (!memory_) return s;
    ERKStepGetNumSteps(memory_, &s.steps);
    ERKStepGetNumErrTestFails(memory_, &s.rejected);
    return s;
  }

  int worstComponent() override {
    if (!memory_ || ERKStepGetEstLocalErrors(memory_, error_) != ARK_SUCCESS ||
        ERKStepGetErrWeights(memory_, weight_) != ARK_SUCCESS)
      return -1;
    return largestWeighted(error_, weight_);
  }

  bool failedInRhs() const override {
    return last_flag_ == ARK_RHSFUNC_FAIL || last_flag_ == ARK_FIRST_RHSFUNC_ERR ||
           last_flag_ == ARK_REPTD_RHSFUNC_ERR || last_flag_ == ARK_UNREC_RHSFUNC_ERR;
  }

  void* memory_ = nullptr;
  N_Vector error_ = nullptr;
  N_Vector weight_ = nullptr;
  int last_flag_ = ARK_SUCCESS;
};

}  // namespace

std::unique_ptr<Integrator> makeArkodeDopri5(const Model& model) {
  return std::make_unique<ArkodeDopri5>(model);
}

}  // namespace tribo
