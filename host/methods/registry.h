// registry.h -- method families: one .cl file plus one host file each.
//
// To add a family (say cubature): write kernels/cubature.cl with a kernel
//   __kernel void render(__global const real* P, __global const float* lum,
//                        __global real* out, int row0, <your arguments>)
// that fills out[row * res + col] for rows row0 .. row0 + get_global_size(1),
// then host/methods/family_cubature.cpp defining
//   void registerCubature(Registry& r) { r.add(Family{...}); }
// (Family and Plan: methods/family.h) with Family::params its parameter
// table, Family::args naming <your arguments> in order (a test holds the
// list to the kernel's CL_KERNEL_ARG_NAME) and Family::plan, the one hook
// that decides a render: it reads the spec once into the program's defines,
// the lanes, the `lum` buffer, every argument of Family::args by name
// (PlanArg), and what the render needs besides (finish, statistics switch,
// passes: Plan); a test builds the plan of every method without a device.
// The rest of Family has defaults. Add its one line to builtinFamilies() in
// registry.cpp.
//
// A method is looked up here once: parseSpec (methods/spec.h) resolves a SPEC
// to its Family and values (MethodSpec), and everything after it -- render(),
// Prepared (methods/render.h), `run`, `tune`, `stability` and `bench` --
// takes that MethodSpec and reads the family from it, so the new family is
// rendered, timed and benchmarked without more code.
//
// Multi-pass methods (the indirect scene's RSM, clustering and evaluation)
// add, beside the one `render` kernel, Plan::prePasses: a function that
// enqueues the kernels to run before `render` on each launch of the image's
// first rows -- any number, in order, each taken from the family's own
// program by LaunchContext::pass(name) (same file, same options) -- and
// returns their events with a stage name ("rsm", "cluster"). The method's
// device time is the sum of those events and the render kernel's (profiling
// events, Prepared::time), so render(), the runner, tune, stability and bench
// time the whole method through the same Prepared path, and
// Prepared::stageMs() gives the per-stage medians (bench's breakdown).
// Their pass kernels and own device buffers are bound by Plan::bind; an
// image filter run after `render` is Plan::postPasses.
// Stateful methods (acrsm keeps its clusters from frame to frame) count their
// launches in LaunchContext::frame, which Prepared::reset() sets back to 0;
// Family::settleFrames says how many launches of a static scene render()
// makes from a reset before it reads the image.
#pragma once

#include "methods/family.h"

#include <string>
#include <vector>

namespace lb::methods {

class Registry {
public:
    void add(Family f);  // Error when a name is registered twice for one scene kind
    const Family* find(const std::string& name, SceneKind kind = SceneKind::Diffuse) const;
    const std::vector<Family>& all() const { return families_; }
    std::string names(SceneKind kind = SceneKind::Diffuse) const;  // "reference|point|..."

private:
    std::vector<Family> families_;
};

// The registry with every built-in family (built once, on first use).
const Registry& registry();
// The family of `name` for scenes of `kind`; InputError listing the valid
// names for that kind when unknown.
const Family& family(const std::string& name, SceneKind kind = SceneKind::Diffuse);
// InputError unless the family renders the scene's light shape (Family::shapes),
// naming the methods that do.
void checkShape(const Family& f, const Scene& scene);

struct TunableRow {
    std::string method;
    Param param;
};

// Every parameter of every registered method, in registration order.
std::vector<TunableRow> tunables();

}  // namespace lb::methods
