package dev.crt.render;

/**
 * The dielectric Fresnel equations for unpolarised light, with η = η₁/η₂ the ratio of the indices
 * on the incident and transmitted sides, cosI the cosine of the angle of incidence and cosT that of
 * refraction (Snell: sin θt = η sin θi).
 */
final class Fresnel {
    private Fresnel() {}

    /** The amplitude reflection coefficient for light polarised perpendicular to the plane of incidence. */
    static double perpendicular(double cosI, double cosT, double eta) {
        return (eta * cosI - cosT) / (eta * cosI + cosT);
    }

    /** The amplitude reflection coefficient for light polarised parallel to the plane of incidence. */
    static double parallel(double cosI, double cosT, double eta) {
        return (cosI - eta * cosT) / (cosI + eta * cosT);
    }

    /** The reflectance (rs² + rp²)/2; the transmittance is 1 minus it. */
    static double reflectance(double cosI, double cosT, double eta) {
        double rs = perpendicular(cosI, cosT, eta), rp = parallel(cosI, cosT, eta);
        return 0.5 * (rs * rs + rp * rp);
    }
}
