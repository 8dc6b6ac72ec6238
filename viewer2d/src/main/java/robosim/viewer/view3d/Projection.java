package robosim.viewer.view3d;

import robosim.protocol.WorldDescription;
import robosim.protocol.WorldDescription.Obstacle;

/**
 * Maps world points (mm; x right, y up the 2D map, z up from the floor) to image pixels for a
 * {@link Camera}: an orthographic projection onto the plane facing the camera, scaled so that at
 * zoom 1 the whole world, walls and robots included, fits the image with a small margin. The
 * depth of a point grows towards the camera, for the painter's algorithm.
 */
public final class Projection {
    /** The height the robots are drawn at, mm: a Pioneer 3 is about 250 mm tall. */
    public static final double ROBOT_HEIGHT_MM = 250;
    private static final double MARGIN = 0.94;

    private final int width;
    private final int height;
    private final double[] right;
    private final double[] up;
    private final double[] towardsCamera;
    private final double scale;
    private final double centreX;
    private final double centreY;

    private Projection(int width, int height, Camera camera, double scale, double centreX, double centreY) {
        this.width = width;
        this.height = height;
        this.towardsCamera = camera.towardsCamera();
        double a = Math.toRadians(camera.azimuth());
        this.right = new double[] {-Math.sin(a), Math.cos(a), 0};
        this.up = cross(towardsCamera, right);
        this.scale = scale;
        this.centreX = centreX;
        this.centreY = centreY;
    }

    /**
     * The projection that fits the world into an image, or centres a point of it.
     *
     * @param world  the world
     * @param camera the camera
     * @param width  image width, px
     * @param height image height, px
     * @param focusX the world x to put in the image's centre, or NaN for the world's own centre
     * @param focusY the world y to put in the image's centre, or NaN
     * @return the projection
     */
    public static Projection fit(WorldDescription world, Camera camera, int width, int height,
                                 double focusX, double focusY) {
        Projection unit = new Projection(width, height, camera, 1, 0, 0);
        double[] box = unit.bounds(world);
        double fit = Math.min(width / Math.max(1e-9, box[2] - box[0]), height / Math.max(1e-9, box[3] - box[1]));
        double scale = fit * MARGIN * camera.zoom();
        double cx = (box[0] + box[2]) / 2;
        double cy = (box[1] + box[3]) / 2;
        if (Double.isFinite(focusX) && Double.isFinite(focusY)) {
            cx = unit.sx(focusX, focusY, 0);
            cy = unit.sy(focusX, focusY, 0);
        }
        return new Projection(width, height, camera, scale, cx, cy);
    }

    /**
     * The image height that suits a camera: the world's projected aspect ratio, kept between a
     * quarter of the width and twice the width.
     *
     * @param world  the world
     * @param camera the camera
     * @param width  image width, px
     * @return the height, px
     */
    public static int heightFor(WorldDescription world, Camera camera, int width) {
        double[] box = new Projection(width, width, camera, 1, 0, 0).bounds(world);
        double aspect = (box[3] - box[1]) / Math.max(1e-9, box[2] - box[0]);
        return (int) Math.max(1, Math.round(width * Math.max(0.25, Math.min(2, aspect))));
    }

    /** @return min sx, min sy, max sx, max sy of the world's box, floor to the tallest thing */
    private double[] bounds(WorldDescription world) {
        double top = ROBOT_HEIGHT_MM;
        for (Obstacle o : world.obstacles()) {
            if (Double.isFinite(o.height())) {
                top = Math.max(top, o.height());
            }
        }
        double[] box = {Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (double x : new double[] {world.minX(), world.minX() + world.width()}) {
            for (double y : new double[] {world.minY(), world.minY() + world.height()}) {
                for (double z : new double[] {0, top}) {
                    box[0] = Math.min(box[0], sx(x, y, z));
                    box[1] = Math.min(box[1], sy(x, y, z));
                    box[2] = Math.max(box[2], sx(x, y, z));
                    box[3] = Math.max(box[3], sy(x, y, z));
                }
            }
        }
        return box;
    }

    private double sx(double x, double y, double z) {
        return x * right[0] + y * right[1] + z * right[2];
    }

    private double sy(double x, double y, double z) {
        return x * up[0] + y * up[1] + z * up[2];
    }

    /**
     * @param x world x, mm
     * @param y world y, mm
     * @param z height above the floor, mm
     * @return the image x of the point, px
     */
    public double px(double x, double y, double z) {
        return width / 2.0 + (sx(x, y, z) - centreX) * scale;
    }

    /**
     * @param x world x, mm
     * @param y world y, mm
     * @param z height above the floor, mm
     * @return the image y of the point, px (down the image)
     */
    public double py(double x, double y, double z) {
        return height / 2.0 - (sy(x, y, z) - centreY) * scale;
    }

    /**
     * @param x world x, mm
     * @param y world y, mm
     * @param z height above the floor, mm
     * @return how near the point is to the camera, mm; greater is nearer
     */
    public double depth(double x, double y, double z) {
        return x * towardsCamera[0] + y * towardsCamera[1] + z * towardsCamera[2];
    }

    /**
     * @param normal a face's outward unit normal
     * @return whether the face turns towards the camera
     */
    public boolean faces(double[] normal) {
        return normal[0] * towardsCamera[0] + normal[1] * towardsCamera[1] + normal[2] * towardsCamera[2] > 1e-9;
    }

    /** @return image width, px */
    public int width() {
        return width;
    }

    /** @return image height, px */
    public int height() {
        return height;
    }

    /** @return pixels per mm */
    public double scale() {
        return scale;
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
}
