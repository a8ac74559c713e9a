/* voronoi.h -- Voronoi-cell cubature weights (thesis 5.1). Compiles as OpenCL
 * C and C++ (see vec.h).
 *
 * Samples on the rectangular light of size w x l, in its plane coordinates
 * (s, t) centred on it: the four corners (in lb_light_corners order), the
 * barycentre and one dynamic point p. Each sample's weight is the area of its
 * planar Voronoi cell on the rectangle divided by the rectangle's area: the
 * thesis precomputed these areas in a texture over p's position (the host
 * builds that table with this code, the kernel looks it up), and used them
 * as fractions of the light's solid angle, E = Omega_L sum_i frac_i L_i G_i
 * (thesis Eq. 5.4 with |T_i| ~ frac_i Omega_L: the planar cells, not the
 * projected ones, the approximation the thesis names).
 * Coincident samples (p on a corner or the barycentre) share their cell
 * equally. */

#define LB_VOR_SITES 6

LB_FN void lb_voronoi_sites(real2 p, real w, real l, real2* s)
{
    s[0] = R2(-R(0.5) * w, -R(0.5) * l);
    s[1] = R2(R(0.5) * w, -R(0.5) * l);
    s[2] = R2(R(0.5) * w, R(0.5) * l);
    s[3] = R2(-R(0.5) * w, R(0.5) * l);
    s[4] = R2(R(0), R(0));
    s[5] = p;
}

/* frac[0..6): cell area fractions of the six sites for the dynamic point p. */
LB_FN void lb_voronoi_fractions(real2 p, real w, real l, real* frac)
{
    real2 s[LB_VOR_SITES];
    lb_voronoi_sites(p, w, l, s);
    real tol = R(1e-6) * (w + l);
    for (int i = 0; i < LB_VOR_SITES; ++i) {
        real3 c[LB_MAXV];
        c[0] = R3(-R(0.5) * w, -R(0.5) * l, R(0));
        c[1] = R3(R(0.5) * w, -R(0.5) * l, R(0));
        c[2] = R3(R(0.5) * w, R(0.5) * l, R(0));
        c[3] = R3(-R(0.5) * w, R(0.5) * l, R(0));
        int n = 4, mult = 1;
        for (int j = 0; j < LB_VOR_SITES && n > 0; ++j) {
            if (j == i)
                continue;
            real2 d = s[i] - s[j];
            if (length(d) <= tol) {
                ++mult; /* coincident: the same cell, shared */
                continue;
            }
            /* keep the points nearer to s_i: x . d >= (s_i + s_j)/2 . d */
            n = lb_clip_polygon(c, n, R3(d.x, d.y, R(0)), dot((s[i] + s[j]) * R(0.5), d));
        }
        frac[i] = n >= 3 ? length(lb_polygon_vector_area(c, n)) / (w * l * (real)mult) : R(0);
    }
}
