package dev.crt.render;

import dev.crt.geom.Vec3;
import dev.crt.scene.Camera;
import dev.crt.scene.Projection;

/**
 * Primary rays of the camera model of rendering-model.md: forward f, right r = (0,1,0)×f, up
 * u = f×r (rolled about f by the left-hand rule), pixel (i, j) with j = 0 at the top, and a thin
 * lens of radius aperture/1000 focused on the plane at focaldistance along f.
 */
final class CameraRays {
    final double px, py, pz;
    final double fx, fy, fz, rx, ry, rz, ux, uy, uz;
    final double width, height, halfHeight, aspect;
    final double lensRadius, focalDistance;
    final ApertureSampler aperture;
    private final Projection projection;

    CameraRays(Camera c, int width, int height) {
        Vec3 p = c.position();
        Vec3 f = c.pointing().minus(p).normalize();
        Vec3 r = Vec3.Y.cross(f);
        r = r.length() == 0 ? Vec3.X : r.normalize();
        Vec3 u = f.cross(r);
        if (c.roll() != 0) {
            double a = Math.toRadians(c.roll()), cos = Math.cos(a), sin = Math.sin(a);
            Vec3 r2 = r.times(cos).plus(u.times(sin));
            u = u.times(cos).minus(r.times(sin));
            r = r2;
        }
        px = p.x();
        py = p.y();
        pz = p.z();
        fx = f.x();
        fy = f.y();
        fz = f.z();
        rx = r.x();
        ry = r.y();
        rz = r.z();
        ux = u.x();
        uy = u.y();
        uz = u.z();
        this.width = width;
        this.height = height;
        halfHeight = Math.tan(Math.toRadians(c.fov()) / 2);
        aspect = (double) width / height;
        projection = c.projection();
        // The 360° projections have no single view axis to focus along: they are pinholes.
        lensRadius = projection == Projection.PERSPECTIVE ? c.aperture() / 1000 : 0;
        focalDistance = c.focalDistance();
        aperture = new ApertureSampler(c.apertureShape());
    }

    boolean hasLens() { return lensRadius > 0; }

    /** Whether every ray leaves the camera's position through the image plane (perspective, no lens). */
    boolean pinhole() {
        return !hasLens() && (!Features.PROJECTIONS || projection == Projection.PERSPECTIVE);
    }

    /**
     * Whether the rays of a block of pixels lie in the block's frustum from the camera, widened by
     * the lens where it has one: perspective, with no lens or one focused at a finite distance.
     */
    boolean framed() {
        return pinhole() || hasLens() && focalDistance > 0 && focalDistance < Double.POSITIVE_INFINITY;
    }

    /**
     * The ray cone's spread (radians) of one pixel along the unit direction d: for perspective
     * 2h/H·(d·f)², the angle a pixel spans in the radial direction there, so that the cone's width
     * stretched by the slant, spread·t/|d·N|, is exactly one pixel's width on a plane facing the
     * camera; for the 360° projections the angle one pixel spans, π/H (spherical) or 2π/W (cylindrical).
     */
    double spread(double[] d) {
        if (!Features.PROJECTIONS || projection == Projection.PERSPECTIVE) {
            double c = d[0] * fx + d[1] * fy + d[2] * fz;
            return 2 * halfHeight / height * c * c;
        }
        return projection == Projection.SPHERICAL ? Math.PI / height : 2 * Math.PI / width;
    }

    /** The pinhole direction through sample (sx, sy) of pixel (i, j), written to {@code d[0..2]}. */
    void direction(int i, int j, double sx, double sy, double[] d) {
        if (Features.PROJECTIONS && projection != Projection.PERSPECTIVE) {
            panoramic(i, j, sx, sy, d);
            return;
        }
        double x = 2 * (i + sx) / width - 1;
        double y = 1 - 2 * (j + sy) / height;
        double a = x * halfHeight * aspect, b = y * halfHeight;
        double dx = fx + a * rx + b * ux, dy = fy + a * ry + b * uy, dz = fz + a * rz + b * uz;
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        d[0] = dx * inv;
        d[1] = dy * inv;
        d[2] = dz * inv;
    }

    /**
     * Spherical: longitude φ = 2π((i + sx)/W − ½), latitude θ = π(½ − (j + sy)/H),
     * d = cosθ·sinφ·r + sinθ·u + cosθ·cosφ·f. Cylindrical: the same φ, d = normalize(sinφ·r + y·h·u + cosφ·f)
     * with y and h as for perspective.
     */
    private void panoramic(int i, int j, double sx, double sy, double[] d) {
        double phi = 2 * Math.PI * ((i + sx) / width - 0.5);
        double sinPhi = Math.sin(phi), cosPhi = Math.cos(phi);
        double a, b, c;
        if (projection == Projection.SPHERICAL) {
            double theta = Math.PI * (0.5 - (j + sy) / height);
            double cosTheta = Math.cos(theta);
            a = cosTheta * sinPhi;
            b = Math.sin(theta);
            c = cosTheta * cosPhi;
        } else {
            a = sinPhi;
            b = (1 - 2 * (j + sy) / height) * halfHeight;
            c = cosPhi;
            double inv = 1 / Math.sqrt(a * a + b * b + c * c);
            a *= inv;
            b *= inv;
            c *= inv;
        }
        d[0] = a * rx + b * ux + c * fx;
        d[1] = a * ry + b * uy + c * fy;
        d[2] = a * rz + b * uz + c * fz;
    }

    /** The length of {@link #aim}'s output. */
    static final int AIM = 4;

    /**
     * The part of {@link #throughLens} that depends on sample (sx, sy) of pixel (i, j) only, made
     * once for all the lens samples of a sub-pixel (a grid sampler's 32 share it): the pinhole
     * direction D (not unit) into {@code aim[0..2]} and (D·f)/F into {@code aim[3]}.
     */
    void aim(int i, int j, double sx, double sy, double[] aim) {
        double x = 2 * (i + sx) / width - 1;
        double y = 1 - 2 * (j + sy) / height;
        double a = x * halfHeight * aspect, b = y * halfHeight;
        double dx = fx + a * rx + b * ux, dy = fy + a * ry + b * uy, dz = fz + a * rz + b * uz;
        aim[0] = dx;
        aim[1] = dy;
        aim[2] = dz;
        aim[3] = (dx * fx + dy * fy + dz * fz) / focalDistance;
    }

    /**
     * The thin-lens ray of the sub-pixel whose {@link #aim} is given, through lens point (lx, ly):
     * origin into {@code o[0..2]}, unit direction into {@code d[0..2]}. The ray aims at the point where the
     * pinhole ray meets the plane in focus, P + D·F/(D·f): with the lens offset L = O − P, its
     * direction is D·F/(D·f) − L, or D − L·(D·f)/F scaled by (D·f)/F. So D need not be a unit
     * vector (one normalisation, not two), and the point in focus is never formed (it overflows
     * when the focal distance is near the largest double).
     */
    void throughLens(double[] aim, double lx, double ly, double[] o, double[] d) {
        double t = aim[3];
        double ox = lensRadius * (lx * rx + ly * ux), oy = lensRadius * (lx * ry + ly * uy),
                oz = lensRadius * (lx * rz + ly * uz);
        o[0] = px + ox;
        o[1] = py + oy;
        o[2] = pz + oz;
        double dx = aim[0] - ox * t, dy = aim[1] - oy * t, dz = aim[2] - oz * t;
        double inv = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        d[0] = dx * inv;
        d[1] = dy * inv;
        d[2] = dz * inv;
    }
}
