/* photometry.h -- luminous intensity lookup (docs/design.md section 3).
 * Compiles as OpenCL C and C++ (see vec.h).
 *
 * A luminaire is one packed float buffer (host/photometry/table.h writes it):
 *   lum[0] = nc, lum[1] = ng                 (counts, stored as floats)
 *   lum[2 .. 2+nc)                           C angles in degrees, ascending, first 0, last 360
 *   lum[2+nc .. 2+nc+ng)                     gamma angles in degrees, ascending
 *   lum[2+nc+ng + ic*ng + ig]                absolute candela at (C[ic], gamma[ig])
 * The C = 360 plane repeats C = 0, so the azimuth never wraps inside a cell. */

#define LB_LUM_HEADER 2

/* Index i of the cell a[i] <= x <= a[i+1] of the ascending array a[0..n), n >= 2,
 * clamped to [0, n-2]. Binary search: the angle grids of real files are not
 * uniform. */
LB_FN int lb_find_cell(__global const float* a, int n, real x)
{
    int lo = 0, hi = n - 1;
    while (hi - lo > 1) {
        int mid = (lo + hi) >> 1;
        if ((real)a[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* Bilinear intensity at (C, gamma) in degrees; C in [0, 360], gamma anywhere
 * (0 outside the measured gamma range). Exact at grid nodes. */
LB_FN real lb_intensity_cg(__global const float* lum, real c_deg, real g_deg)
{
    int nc = (int)lum[0];
    int ng = (int)lum[1];
    __global const float* ca = lum + LB_LUM_HEADER;
    __global const float* ga = ca + nc;
    __global const float* val = ga + ng;
    if (g_deg < (real)ga[0] || g_deg > (real)ga[ng - 1])
        return R(0);
    int ic = lb_find_cell(ca, nc, c_deg);
    int ig = lb_find_cell(ga, ng, g_deg);
    real c0 = (real)ca[ic], c1 = (real)ca[ic + 1];
    real g0 = (real)ga[ig], g1 = (real)ga[ig + 1];
    real tc = c1 > c0 ? clamp((c_deg - c0) / (c1 - c0), R(0), R(1)) : R(0);
    real tg = g1 > g0 ? clamp((g_deg - g0) / (g1 - g0), R(0), R(1)) : R(0);
    __global const float* r0 = val + ic * ng + ig;
    __global const float* r1 = r0 + ng;
    real a = mix((real)r0[0], (real)r0[1], tg);
    real b = mix((real)r1[0], (real)r1[1], tg);
    return mix(a, b, tc);
}

/* Photometric angles of the emission direction d given in the luminaire frame
 * (d.x along u, d.y along v, d.z along n_L); d need not be normalised. */
LB_FN real lb_gamma_deg(real3 d)
{
    return atan2(sqrt(d.x * d.x + d.y * d.y), d.z) * LB_DEG;
}

LB_FN real lb_c_deg(real3 d)
{
    real c = atan2(d.y, d.x) * LB_DEG;
    return c < R(0) ? c + R(360) : c;
}

/* Intensity (cd) emitted in direction d, d in the luminaire frame. The one
 * switch between lookups: a kernel built with -DLB_LUT takes the packed
 * trig-free table of lut.h as `lum` instead (the reference never does). */
LB_FN real lb_intensity_local(__global const float* lum, real3 d)
{
#ifdef LB_LUT
    return lb_lut_intensity(lum, d);
#else
    return lb_intensity_cg(lum, lb_c_deg(d), lb_gamma_deg(d));
#endif
}

/* The same from scalar components, for scalar hot loops (no float3 there, so
 * that the loop vectoriser can take them). */
#ifdef LB_LUT
#define LB_INTENSITY3(lum, x, y, z) lb_lut_intensity3((lum), (x), (y), (z))
#else
#define LB_INTENSITY3(lum, x, y, z) lb_intensity_local((lum), R3((x), (y), (z)))
#endif
