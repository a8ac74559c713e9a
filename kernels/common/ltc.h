/* ltc.h -- Linearly Transformed Cosines (Heitz, Dupuy, Hill, Neubelt 2016)
 * for the GGX BRDF of ggx.h: the polygon integral of f_r cos and the table
 * lookup. Compiles as OpenCL C and C++ (see vec.h).
 *
 * An LTC is the clamped cosine D_o(w) = max(0, w_z) / pi transformed by a
 * 3x3 matrix M: D(w) = D_o(w_o) |det M^-1| / |M^-1 w|^3, w_o = M^-1 w / |M^-1 w|.
 * The fit (host/ltc/fit.h, `lumibench ltc fit`) makes norm * D close to
 * f_r(w, w_o) cos for each (alpha, theta_o), in the view frame of ggx.h
 * (lb_view_frame: w_o = (sin theta_o, 0, cos theta_o)), where M^-1 has the
 * form [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]] (normalised by its middle
 * element; the integral below does not depend on M's scale) and
 * norm = int f_r cos dw is the BRDF's directional albedo.
 *
 * The integral of D over a polygon P is the integral of D_o over M^-1 P
 * (the transformed polygon, clipped to the horizon z >= 0 of the cosine):
 * Lambert's formula (spherical.h lb_polygon_irradiance_lambert) divided by pi.
 *
 * The table (host/ltc/table.h packs it) is one float buffer:
 *   ltc[0] = n (grid size, a float), then for cell (i, j), i the roughness
 *   index (sqrt(alpha) = i / (n - 1)) and j the view index (theta_o =
 *   j / (n - 1) * pi / 2), the 5 floats m00, m02, m20, m22, norm at
 *   ltc[1 + 5 (j n + i) ..]. */

#define LB_LTC_HEADER 1
#define LB_LTC_STRIDE 5

/* Integral of the LTC with inverse matrix m = (m00, m02, m20, m22) over the
 * convex polygon p[0..n) (positions relative to the shading point in the view
 * frame, any winding, at most 5 vertices); modifies nothing. In [0, 1]. */
LB_FN real lb_ltc_polygon(const real3* p, int n, real m00, real m02, real m20, real m22)
{
    real3 q[LB_MAXV];
    for (int i = 0; i < n; ++i)
        q[i] = R3(m00 * p[i].x + m02 * p[i].z, p[i].y, m20 * p[i].x + m22 * p[i].z);
    int m = lb_clip_polygon(q, n, R3(0, 0, 1), R(0));
    if (m < 3)
        return R(0);
    return lb_polygon_irradiance_lambert(q, m, R3(0, 0, 1)) / LB_PI;
}

/* The LTC at (alpha, cos theta_o): bilinear in (sqrt(alpha), theta_o) between
 * the table's nodes, clamped to its range. c[0..5) = m00, m02, m20, m22, norm. */
LB_FN void lb_ltc_lookup(__global const float* ltc, real alpha, real cos_o, real* c)
{
    int n = (int)ltc[0];
    real fa = clamp(sqrt(fmax(alpha, R(0))), R(0), R(1)) * (real)(n - 1);
    real th = acos(clamp(cos_o, R(0), R(1)));
    real ft = clamp(th / (R(0.5) * LB_PI), R(0), R(1)) * (real)(n - 1);
    int i0 = LB_IMIN((int)fa, n - 2), j0 = LB_IMIN((int)ft, n - 2);
    real sa = fa - (real)i0, st = ft - (real)j0;
    __global const float* c00 = ltc + LB_LTC_HEADER + LB_LTC_STRIDE * (j0 * n + i0);
    __global const float* c10 = c00 + LB_LTC_STRIDE;
    __global const float* c01 = c00 + LB_LTC_STRIDE * n;
    __global const float* c11 = c01 + LB_LTC_STRIDE;
    for (int k = 0; k < LB_LTC_STRIDE; ++k)
        c[k] = mix(mix((real)c00[k], (real)c10[k], sa), mix((real)c01[k], (real)c11[k], sa), st);
}

/* The LTC estimate of int_P f_r(w, w_o) cos dw for the polygon p[0..n)
 * (world positions relative to the shading point, receiver normal nx, unit
 * view direction wo, at most 5 vertices): norm * int_P D. */
LB_FN real lb_ltc_brdf_polygon(__global const float* ltc, const real3* p, int n, real3 nx, real3 wo, real alpha)
{
    real3 t1, t2;
    lb_view_frame(nx, wo, &t1, &t2);
    real c[LB_LTC_STRIDE];
    lb_ltc_lookup(ltc, alpha, dot(nx, wo), c);
    real3 q[LB_MAXV];
    for (int i = 0; i < n; ++i)
        q[i] = R3(dot(p[i], t1), dot(p[i], t2), dot(p[i], nx));
    return c[4] * lb_ltc_polygon(q, n, c[0], c[1], c[2], c[3]);
}
