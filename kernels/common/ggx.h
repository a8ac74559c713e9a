/* ggx.h -- the glossy receiver's BRDF (docs/design.md section 8): isotropic GGX
 * microfacet, no Fresnel (F = 1), alpha given directly,
 *   f_r(w_i, w_o) = D(h) G2(w_i, w_o) / (4 cos_i cos_o),
 *   D(h) = alpha^2 / (pi (cos_h^2 (alpha^2 - 1) + 1)^2)       (Trowbridge-Reitz)
 *   G2 = 1 / (1 + Lambda(w_i) + Lambda(w_o))                  (height-correlated Smith)
 *   Lambda(w) = (-1 + sqrt(1 + alpha^2 tan^2 theta)) / 2.
 * Compiles as OpenCL C and C++ (see vec.h). Directions are given in the
 * receiver's local frame (z along the normal) by scalar components, so the
 * hot loops stay scalar; they need not be normalised.
 *
 * The evaluation form. With h = w_i + w_o (unnormalised), for unit w_i, w_o:
 *   D = alpha^2 |h|^4 / (pi (alpha^2 h_z^2 + h_x^2 + h_y^2)^2)
 * (cos_h^2 = h_z^2 / |h|^2 multiplied through: no cancellation near the
 * normal), and with S(w) = sqrt(z^2 + alpha^2 (x^2 + y^2)) = z (1 + 2 Lambda(w)),
 *   G2 = 2 z_i z_o / (z_o S_i + z_i S_o),
 *   f_r = D / (2 (z_o S_i + z_i S_o)),
 * finite for every direction above the horizon (the 1 / (cos_i cos_o) of the
 * textbook form cancels against G2). Symmetric in (w_i, w_o) by form
 * (Helmholtz reciprocity; tests/specular checks it and the textbook form). */

/* Smith Lambda of the direction (x, y, z), z > 0 (docs/design.md section 8's form; for the
 * tests and the VNDF sampler; f_r uses S = z (1 + 2 Lambda) directly). */
LB_FN real lb_ggx_lambda(real x, real y, real z, real alpha)
{
    real t2 = (x * x + y * y) / (z * z);
    return R(0.5) * (sqrt(R(1) + alpha * alpha * t2) - R(1));
}

/* D(h) and f_r, lane-generic (ggx_lanes.inc), here for one pixel: lb_ggx_d,
 * lb_ggx_brdf. */
#include "lanes1.h"
#include "ggx_lanes.inc"
#include "lanes_end.h"

/* f_r(w_i, w_o) cos_i (unit directions): the integrand of the reflected
 * radiance per unit incident radiance and solid angle. */
LB_FN real lb_ggx_brdf_cos(real ix, real iy, real iz, real ox, real oy, real oz, real alpha)
{
    return lb_ggx_brdf(ix, iy, iz, ox, oy, oz, alpha) * iz;
}

/* Local frame of the receiver at normal n and view direction wo (unit): t1
 * along wo's tangential part (any tangent when wo is along n), t2 = n x t1;
 * the LTC tables are fitted in this frame (wo = (sin theta_o, 0, cos theta_o)). */
LB_FN void lb_view_frame(real3 n, real3 wo, real3* t1, real3* t2)
{
    real3 t = wo - n * dot(n, wo);
    real l = length(t);
    if (l > R(1e-7) * length(wo)) {
        *t1 = t / l;
    } else {
        real3 a = fabs(n.x) < R(0.9) ? R3(1, 0, 0) : R3(0, 1, 0);
        *t1 = normalize(cross(a, n));
    }
    *t2 = cross(n, *t1);
}

/* Visible-normal sampling of GGX (Heitz 2018, "Sampling the GGX Distribution
 * of Visible Normals"): a microfacet normal m drawn with density
 * D_o(m) = G1(w_o) max(0, w_o . m) D(m) / cos_o for the unit view direction
 * (ox, oy, oz), oz > 0, from (u1, u2) in [0, 1)^2 (returned in the frame of
 * (ox, oy, oz): z along the normal). The reflected direction
 * w_i = 2 (w_o . m) m - w_o then has density D_o(m) / (4 w_o . m), and the
 * estimator f_r cos_i / pdf = G2 / G1(w_o) (no D left). */
LB_FN real3 lb_ggx_sample_vndf(real ox, real oy, real oz, real alpha, real u1, real u2)
{
    /* stretch the view direction to the hemisphere configuration */
    real vx = alpha * ox, vy = alpha * oy, vz = oz;
    real vl = sqrt(vx * vx + vy * vy + vz * vz);
    vx /= vl;
    vy /= vl;
    vz /= vl;
    /* orthonormal basis (t1, t2, v) */
    real lensq = vx * vx + vy * vy;
    real t1x = R(1), t1y = R(0), t1z = R(0);
    if (lensq > R(0)) {
        real il = R(1) / sqrt(lensq);
        t1x = -vy * il;
        t1y = vx * il;
    }
    real t2x = vy * t1z - vz * t1y, t2y = vz * t1x - vx * t1z, t2z = vx * t1y - vy * t1x;
    /* a point on the projected area */
    real r = sqrt(u1);
    real phi = LB_TWO_PI * u2;
    real p1 = r * cos(phi), p2 = r * sin(phi);
    real s = R(0.5) * (R(1) + vz);
    p2 = (R(1) - s) * sqrt(fmax(R(0), R(1) - p1 * p1)) + s * p2;
    real p3 = sqrt(fmax(R(0), R(1) - p1 * p1 - p2 * p2));
    real nx = p1 * t1x + p2 * t2x + p3 * vx;
    real ny = p1 * t1y + p2 * t2y + p3 * vy;
    real nz = p1 * t1z + p2 * t2z + p3 * vz;
    /* unstretch */
    nx *= alpha;
    ny *= alpha;
    nz = fmax(R(0), nz);
    real nl = sqrt(nx * nx + ny * ny + nz * nz);
    return R3(nx / nl, ny / nl, nz / nl);
}

/* Density (per solid angle of w_i) of the VNDF sampler's reflected direction:
 * D(h) G1(w_o) / (4 cos_o), h = normalize(w_i + w_o); unit directions. */
LB_FN real lb_ggx_vndf_pdf(real ix, real iy, real iz, real ox, real oy, real oz, real alpha)
{
    if (!(oz > R(0)))
        return R(0);
    real hx = ix + ox, hy = iy + oy, hz = iz + oz;
    if (!(hz > R(0)))
        return R(0);
    real g1 = R(1) / (R(1) + lb_ggx_lambda(ox, oy, oz, alpha));
    return lb_ggx_d(hx, hy, hz, alpha) * g1 / (R(4) * oz);
}
