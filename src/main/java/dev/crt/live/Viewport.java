package dev.crt.live;

import dev.crt.geom.Vec3;

/** The views a live view viewport can show. */
public enum Viewport {
    FREE("Free", null, null, -1),
    SCENE_CAMERA("Scene camera", null, null, -1),
    TOP("Top", new Vec3(0, -1, 0), new Vec3(0, 0, 1), 1),
    FRONT("Front", new Vec3(0, 0, 1), new Vec3(0, 1, 0), 2),
    SIDE("Side", new Vec3(-1, 0, 0), new Vec3(0, 1, 0), 0);

    private final String label;
    final Vec3 forward, up;
    /** The axis across the grid's plane (0 x, 1 y, 2 z), −1 for perspective views without a grid. */
    final int gridAxis;

    Viewport(String label, Vec3 forward, Vec3 up, int gridAxis) {
        this.label = label;
        this.forward = forward;
        this.up = up;
        this.gridAxis = gridAxis;
    }

    public String label() { return label; }

    public boolean isOrthographic() { return forward != null; }
}
