/* spherical.h -- solid angles and exact irradiance of polygons seen from a point.
 * Compiles as OpenCL C and C++ (see vec.h). Directions need not be normalised. */

/* Signed solid angle of the spherical triangle (a, b, c) seen from the origin,
 * positive when det(a, b, c) > 0. Van Oosterom & Strackee (1983) in atan2 form
 * on unnormalised vectors: the result converges to 0 as the triangle
 * degenerates (two equal vertices or three coplanar with the origin), which the
 * cubature needs for the thin triangles next to the closest point (paper 5.2). */
LB_FN real lb_tri_solid_angle(real3 a, real3 b, real3 c)
{
    real la = length(a), lb = length(b), lc = length(c);
    /* det(a, b, c) = a . ((b - a) x (c - a)). For a small far triangle (size s
     * at distance d) a . (b x c) cancels: b x c ~ d s carries rounding errors
     * ~ eps d^2, so det ~ d s^2 came out with relative error eps (d/s)^2 (a
     * 1 mm light at 1 m: 0.12 in float, the far-field / tiny-light failures of
     * lumibench stability). The edge vectors are formed first (exact for
     * nearby vertices), their cross product ~ s^2 is accurate to eps, and the
     * determinant to eps relative. */
    real num = dot(a, cross(b - a, c - a));
    real den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    return R(2) * atan2(num, den);
}

/* Solid angle of the convex polygon p[0..n) (positions relative to the viewing
 * point), any orientation: a fan of signed triangles, then the magnitude. */
LB_FN real lb_polygon_solid_angle(const real3* p, int n)
{
    real s = R(0);
    for (int i = 1; i + 1 < n; ++i)
        s += lb_tri_solid_angle(p[0], p[i], p[i + 1]);
    return fabs(s);
}

/* Angle between two directions, accurate also near 0 and pi (acos is not). */
LB_FN real lb_angle_between(real3 a, real3 b)
{
    return atan2(length(cross(a, b)), dot(a, b));
}

/* Irradiance at the origin, receiver normal nx, from the convex polygon
 * p[0..n) (relative positions, entirely on the positive side of nx: clip
 * first) of unit Lambertian radiance: Lambert's formula (Baum et al. 1989),
 *   E = 1/2 | sum_i Theta_i  nx . (p_i x p_i+1) / |p_i x p_i+1| |,
 * Theta_i the angle subtended by edge i. Multiply by the radiance for lux.
 * Written as sum_i w_i nx . c_i with c_i = p_i x p_i+1, w_i = Theta_i / |c_i|.
 * For a small far polygon (size s, distance d) the terms ~ s/d cancel to a
 * sum ~ (s/d)^2, and the c_i carry relative errors eps d/s: the plain sum was
 * off by eps (d/s)^2 (5 % in float for a 1 mm light at 1.3 m: cubature with
 * normalize=formfactor in lumibench stability's `tiny` case). Split instead
 *   sum_i w_i c_i = sum_i (w_i - w_0) c_i + w_0 sum_i (p_i - p_0) x (p_i+1 - p_0)
 * (the cyclic sum of p_i x p_i+1 equals that of the edge vectors about any
 * point): the second sum is twice the area vector from short edge vectors
 * (accurate to eps), the first has small weights w_i - w_0 ~ w s/d, so its
 * rounding is eps d/s of a term that is itself s/d of the result (tested in
 * tests/stability/test_stability_fixes.cpp). */
LB_FN real lb_polygon_irradiance_lambert(const real3* p, int n, real3 nx)
{
    real s = R(0), w0 = R(0);
    real3 area = R3(0, 0, 0);
    for (int i = 0; i < n; ++i) {
        real3 a = p[i];
        real3 b = p[(i + 1 == n) ? 0 : i + 1];
        real3 c = cross(a, b);
        real lc = length(c);
        real ab = dot(a, b);
        /* w = Theta / |c| -> 1 / (a . b) as the edge's angle goes to 0; an
         * edge through the origin (a . b <= 0, c = 0) contributes nothing. */
        real w = lc > R(0) ? atan2(lc, ab) / lc : (ab > R(0) ? R(1) / ab : R(0));
        /* The split pays for small polygons only; for a large one (edge 0
         * subtending > 0.25 rad) its two sums cancel instead: w0 = 0 there,
         * the plain formula (the same value up to rounding). */
        if (i == 0)
            w0 = atan2(lc, ab) < R(0.25) ? w : R(0);
        s += (w - w0) * dot(nx, c);
        if (i > 0 && i + 1 < n)
            area += cross(a - p[0], b - p[0]);
    }
    return R(0.5) * fabs(s + w0 * dot(nx, area));
}
