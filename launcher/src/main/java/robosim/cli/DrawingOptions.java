package robosim.cli;

import picocli.CommandLine.Option;
import robosim.viewer.draw.SnapshotPainter;
import robosim.viewer.draw.RenderOptions;
import robosim.viewer.draw.WorldRenderer;
import robosim.viewer.view3d.Camera;
import robosim.viewer.view3d.Light;
import robosim.viewer.view3d.SceneOptions;
import robosim.viewer.view3d.SolidRenderer;
import robosim.viewer.window.ViewState;

/** How images are drawn, shared by {@code viewer} and {@code replay}: 2D or 3D, and what to show. */
final class DrawingOptions {
    @Option(names = "--width", defaultValue = "800", paramLabel = "PX", description = "frame width in pixels; default ${DEFAULT-VALUE}")
    int width;

    @Option(names = "--sonar", description = "draw the sonar rays")
    boolean sonar;

    @Option(names = "--no-names", description = "do not label the robots")
    boolean noNames;

    @Option(names = "--trails", description = "draw the path each robot has taken")
    boolean trails;

    @Option(names = "--grid", description = "draw a light grid of round-length squares (2D)")
    boolean grid;

    @Option(names = "--drawings", description = OptionTexts.DRAWINGS)
    boolean drawings;

    @Option(names = "--3d", description = "draw the 3D view: walls extruded to their heights, robots as solids")
    boolean threeD;

    @Option(names = "--azimuth", defaultValue = "-90", paramLabel = "DEG",
            description = "3D: compass direction from the world's centre to the camera, degrees counter-clockwise from +x (-90: from the south); default ${DEFAULT-VALUE}")
    double azimuth;

    @Option(names = "--elevation", defaultValue = "40", paramLabel = "DEG",
            description = "3D: the camera's angle above the ground, 5 to 90; default ${DEFAULT-VALUE}")
    double elevation;

    @Option(names = "--zoom", defaultValue = "1", paramLabel = "X", description = "3D: magnification, 1 fits the world; default ${DEFAULT-VALUE}")
    double zoom;

    @Option(names = "--light", defaultValue = "-135,55", paramLabel = "AZ,EL",
            description = "3D: direction towards the light, azimuth and elevation in degrees; default ${DEFAULT-VALUE}")
    String light;

    /** @return the 2D options; throws IllegalArgumentException naming a bad value */
    RenderOptions render() {
        return new RenderOptions(width, sonar, !noNames).withTrails(trails).withGrid(grid).withDrawings(drawings);
    }

    /** @return the 3D options; throws IllegalArgumentException naming a bad value */
    SceneOptions scene() {
        // as in 2D: laser scans always, sonar rays with --sonar, and the legend under the scene
        return new SceneOptions(width, new Camera(azimuth, elevation, zoom), light(), !noNames, trails, true, sonar,
                true, true);
    }

    private Light light() {
        String[] parts = light.split(",");
        if (parts.length != 2) {
            throw new IllegalArgumentException("'" + light + "' was supplied for --light: it must be AZ,EL in degrees, such as -135,55");
        }
        try {
            return new Light(Double.parseDouble(parts[0].strip()), Double.parseDouble(parts[1].strip()));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + light + "' was supplied for --light: it must be AZ,EL in degrees, such as -135,55");
        }
    }

    /** Checks every option, 2D and 3D alike; throws IllegalArgumentException naming a bad value. */
    void validate() {
        render();
        scene();
    }

    /** @return the painter for PNG and GIF images; throws IllegalArgumentException naming a bad value */
    SnapshotPainter painter() {
        return threeD ? new SolidRenderer(scene()) : SnapshotPainter.flat(new WorldRenderer(), render());
    }

    /** @return the window's initial state, as these options say */
    ViewState windowState() {
        ViewState state = new ViewState();
        state.setRender(render());
        SceneOptions scene = scene();
        state.setThreeD(threeD);
        state.setCamera(scene.camera());
        state.setLight(scene.light());
        return state;
    }
}
