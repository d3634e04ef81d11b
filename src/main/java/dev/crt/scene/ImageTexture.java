package dev.crt.scene;

import dev.crt.geom.Transform;
import dev.crt.geom.Vec3;

/**
 * A picture on a surface: the point goes to texture space q = T⁻¹·p (T = scale, then rotate, then
 * offset; p the entity point, or (u, v, 0) for the "uv" mapping), the mapping turns q into image
 * coordinates (s, t), and the mip chain is sampled trilinearly at the level of the ray's
 * footprint (docs/rendering.md, "Image textures"). {@code path} is the resolved file.
 */
public final class ImageTexture implements Texture {
    private final String path;
    private final Picture picture;
    private final TextureMapping mapping;
    private final Vec3 scale, rotate, offset;
    /** T⁻¹ as a row-major 3×4 matrix, and the factor by which it shrinks lengths (cube root of its determinant). */
    private final double[] inverse;
    private final double lengthFactor;
    private final MipMap mip;

    public ImageTexture(String path, Picture picture, TextureMapping mapping, Vec3 scale, Vec3 rotate, Vec3 offset) {
        this(path, picture, mapping, scale, rotate, offset, new MipMap(picture, 1));
    }

    private ImageTexture(String path, Picture picture, TextureMapping mapping, Vec3 scale, Vec3 rotate, Vec3 offset,
            MipMap mip) {
        this.path = path;
        this.picture = picture;
        this.mapping = mapping;
        this.scale = scale;
        this.rotate = rotate;
        this.offset = offset;
        inverse = Transform.scaling(scale).then(Transform.rotation(rotate)).then(Transform.translation(offset)).inverseMatrix();
        double[] m = inverse;
        double det = m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) + m[2] * (m[4] * m[9] - m[5] * m[8]);
        lengthFactor = Math.cbrt(Math.abs(det));
        this.mip = mip;
    }

    public String path() { return path; }

    public Picture picture() { return picture; }

    public TextureMapping mapping() { return mapping; }

    public Vec3 scale() { return scale; }

    public Vec3 rotate() { return rotate; }

    public Vec3 offset() { return offset; }

    /** The mip chain it samples: texels as stored, or decoded to linear light once {@link #prepared} for a gamma ≠ 1. */
    public MipMap mipMap() { return mip; }

    @Override
    public boolean needsUv() { return mapping == TextureMapping.UV; }

    @Override
    public Texture prepared(double gamma) {
        if (gamma == 1) return this;
        return new ImageTexture(path, picture, mapping, scale, rotate, offset, new MipMap(picture, gamma));
    }

    @Override
    public void evaluate(TexturePoint p, double[] out) {
        MipMap m = mip;
        double px, py, pz;
        if (mapping == TextureMapping.UV) {
            px = p.u;
            py = p.v;
            pz = 0;
        } else {
            px = p.x;
            py = p.y;
            pz = p.z;
        }
        double[] a = inverse;
        double qx = a[0] * px + a[1] * py + a[2] * pz + a[3];
        double qy = a[4] * px + a[5] * py + a[6] * pz + a[7];
        double qz = a[8] * px + a[9] * py + a[10] * pz + a[11];
        double width = p.width * lengthFactor;
        double s, t, ws, wt;
        switch (mapping) {
            case UV -> {
                s = qx;
                t = qy;
                ws = p.widthU * lengthFactor;
                wt = p.widthV * lengthFactor;
            }
            case PLANAR -> {
                s = qx;
                t = -qy;
                ws = width;
                wt = width;
            }
            case SPHERICAL -> {
                double rho = Math.sqrt(qx * qx + qz * qz), r = Math.sqrt(rho * rho + qy * qy);
                s = 0.5 + Math.atan2(qx, qz) * (0.5 / Math.PI);
                t = r > 0 ? Math.acos(Math.max(-1, Math.min(1, qy / r))) / Math.PI : 0.5;
                ws = width / (2 * Math.PI * rho);
                wt = width / (Math.PI * r);
            }
            case CYLINDRICAL -> {
                double rho = Math.sqrt(qx * qx + qz * qz);
                s = 0.5 + Math.atan2(qx, qz) * (0.5 / Math.PI);
                t = -qy;
                ws = width / (2 * Math.PI * rho);
                wt = width;
            }
            default -> {
                // Box: project along the entity normal's dominant axis.
                double ax = Math.abs(p.nx), ay = Math.abs(p.ny), az = Math.abs(p.nz);
                if (ax >= ay && ax >= az) {
                    s = p.nx > 0 ? -qz : qz;
                    t = -qy;
                } else if (ay >= az) {
                    s = qx;
                    t = p.ny > 0 ? qz : -qz;
                } else {
                    s = p.nz > 0 ? qx : -qx;
                    t = -qy;
                }
                ws = width;
                wt = width;
            }
        }
        m.sample(s, t, m.level(ws, wt), out);
    }

    @Override
    public String toString() {
        return "ImageTexture[" + path + ", " + mapping.scriptName() + "]";
    }
}
