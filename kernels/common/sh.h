/* sh.h -- the integral over a spherical polygon of a band-limited function
 * written in zonal lobes, the kernel side of the `sh` method (sh.cl; the fit
 * and the lobes are made on the host, host/methods/sh_fit.h).
 *
 * The function: q(u) = sum_{l=0}^{nb-1} sum_{j<nd} b_lj P_l(w_j . u), P_l the
 * Legendre polynomials, w_j unit directions (any polynomial of degree nb - 1
 * on the sphere is such a sum once nd >= 2 nb - 1: the addition theorem per
 * band). Its integral over the convex spherical polygon A (vertices p_i,
 * relative to the viewing point, any length):
 *   band 0:   b_0j |A|;
 *   band l:   P_l(w . u) is an eigenfunction of the sphere's Laplacian
 *             (eigenvalue -l (l + 1)), so by the divergence theorem
 *             int_A P_l(w . u) du = 1 / (l (l + 1)) sum_edges (w . m_e) D_l(e),
 *             m_e = p_i x p_i+1 / |.| (A counter-clockwise seen from outside;
 *             the sign flips with the winding) and D_l = int_0^Theta
 *             P_l'(c(phi)) dphi along the edge's great arc,
 *             c(phi) = x cos phi + y sin phi, x = w . a, y = w . t (a the
 *             edge's first vertex, t = m_e x a its tangent there).
 * The edge integrals by a two-term recurrence (this suite's derivation, no
 * monomials: P_l's monomial coefficients reach 1e4 at l = 16 and cancel in
 * float): with B_l = int_0^Theta P_l(c) dphi, s(phi) = c'(phi),
 * T_l = [P_l(c) s]_0^Theta and k = (w . m_e)^2 = 1 - x^2 - y^2,
 *   D_0 = 0, D_1 = Theta, B_0 = Theta, B_1 = -T_0,
 *   D_{l+1} = D_{l-1} + (2l + 1) B_l                  (P'_{l+1} - P'_{l-1} = (2l+1) P_l),
 *   B_{l+1} = (l^2 B_{l-1} - (2l + 1) (k D_l + T_l)) / (l + 1)^2
 * (the second from d/dphi [P_l(c) s] = P_l'(c) s^2 - c P_l(c) with
 * s^2 = 1 - k - c^2, (1 - c^2) P_l' = l (P_{l-1} - c P_l) and Bonnet's
 * recursion), P_l at the arc's ends by Bonnet's recursion. Every quantity
 * stays bounded by its exact value's size (|B_l| <= Theta, |D_l| <=
 * l (l + 1) Theta / 2), which keeps it stable in float to l = 17
 * (tests/math/test_sh.cpp).
 *
 * Layout of zc: nd directions (x, y, z), then the coefficients band by band,
 * zc[3 nd + l nd + j] = b_lj / (l (l + 1)) for l >= 1 (the host divides) and
 * b_0j for l = 0. */

/* The part of the integral the edge a -> b (unit vectors) adds for every
 * band l >= 1, summed over the lobes: sum_j (w_j . m) sum_l b'_lj D_l. */
LB_FN real lb_sh_edge(real3 a, real3 b, __global const real* zc, int nb, int nd, real3* mtheta)
{
    real3 cr = cross(a, b);
    real lc = length(cr);
    if (!(lc > R(0)))
        return R(0); /* a degenerate edge adds nothing */
    real3 m = cr / lc;
    real theta = atan2(lc, dot(a, b));
    *mtheta += m * theta;
    real3 t = cross(m, a), tb = cross(m, b);
    __global const real* cf = zc + 3 * nd;
    real acc = R(0);
    for (int j = 0; j < nd; ++j) {
        real3 w = R3(zc[3 * j], zc[3 * j + 1], zc[3 * j + 2]);
        real x = dot(w, a), y = dot(w, t), c1 = dot(w, b), s1 = dot(w, tb), wm = dot(w, m);
        real k = wm * wm;
        real pa0 = R(1), pa = x, pb0 = R(1), pb = c1;
        real b0 = theta, b1 = y - s1, d0 = R(0), d1 = theta;
        real sum = cf[nd + j] * d1;
        for (int l = 1; l + 1 < nb; ++l) {
            real fl = (real)l, f2 = R(2) * fl + R(1), fl1 = fl + R(1);
            real tl = pb * s1 - pa * y;
            real bn = (fl * fl * b0 - f2 * (k * d1 + tl)) / (fl1 * fl1);
            real dn = d0 + f2 * b1;
            real pan = (f2 * x * pa - fl * pa0) / fl1, pbn = (f2 * c1 * pb - fl * pb0) / fl1;
            pa0 = pa;
            pa = pan;
            pb0 = pb;
            pb = pbn;
            b0 = b1;
            b1 = bn;
            d0 = d1;
            d1 = dn;
            sum += cf[(l + 1) * nd + j] * d1;
        }
        acc += wm * sum;
    }
    return acc;
}

/* int_A q(u) du over the convex polygon p[0..n) (relative positions, any
 * winding): the lobes' layout zc above, nb bands, nd directions. */
LB_FN real lb_sh_polygon(const real3* p, int n, __global const real* zc, int nb, int nd)
{
    real b0 = R(0);
    for (int j = 0; j < nd; ++j)
        b0 += zc[3 * nd + j];
    real e = b0 * lb_polygon_solid_angle(p, n);
    if (nb < 2)
        return e;
    real3 mtheta = R3(0, 0, 0), mid = R3(0, 0, 0);
    real acc = R(0);
    for (int i = 0; i < n; ++i) {
        real3 a = normalize(p[i]), b = normalize(p[(i + 1 == n) ? 0 : i + 1]);
        mid += a;
        acc += lb_sh_edge(a, b, zc, nb, nd, &mtheta);
    }
    /* the winding: sum_e m_e Theta_e is twice the polygon's first moment,
     * which points into it when it turns counter-clockwise seen from outside */
    return dot(mtheta, mid) >= R(0) ? e + acc : e - acc;
}
