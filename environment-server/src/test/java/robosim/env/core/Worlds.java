package robosim.env.core;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import robosim.env.world.Obstacle;
import robosim.env.world.RobotSpec;
import robosim.env.world.World;
import robosim.params.ParameterFileReader;
import robosim.protocol.RobotParameters;

/** Literal worlds for the core's tests. */
final class Worlds {
    private Worlds() {
    }

    static Path root() {
        String prop = System.getProperty("robosim.root");
        Path p = prop != null ? Path.of(prop) : Path.of("").toAbsolutePath();
        while (p != null && !Files.isDirectory(p.resolve("testLoadFiles"))) {
            p = p.getParent();
        }
        if (p == null) {
            throw new IllegalStateException("cannot find testLoadFiles above " + Path.of("").toAbsolutePath());
        }
        return p;
    }

    static RobotParameters p3dx() {
        return ParameterFileReader.read(root().resolve("testLoadFiles/robots/p3dx.p"));
    }

    /** A p3dx with other limits: the same body and sonars. */
    static RobotParameters p3dxWith(double maxVel, double accel) {
        RobotParameters p = p3dx();
        return new RobotParameters(p.robotClass(), p.subclass(), p.robotRadius(), p.robotWidth(),
                p.robotLengthFront(), p.robotLengthRear(), maxVel, p.maxRVelocity(), accel, accel,
                p.rotAccel(), p.rotDecel(), p.diffConvFactor(), p.sonarMaxRange(), p.sonarUnits());
    }

    /** A p3dx whose laser is mounted at the given pose. */
    static RobotParameters p3dxWithLaser(double lx, double ly, double lth) {
        RobotParameters p = p3dx();
        return new RobotParameters(p.robotClass(), p.subclass(), p.robotRadius(), p.robotWidth(),
                p.robotLengthFront(), p.robotLengthRear(), p.maxVelocity(), p.maxRVelocity(), p.transAccel(),
                p.transDecel(), p.rotAccel(), p.rotDecel(), p.diffConvFactor(), p.sonarMaxRange(), p.sonarUnits(),
                lx, ly, lth, 8000);
    }

    static RobotSpec robot(String name, double x, double y, double th) {
        return robot(name, x, y, th, p3dx());
    }

    static RobotSpec robot(String name, double x, double y, double th, RobotParameters p) {
        return new RobotSpec(name, "pioneer", x, y, th, Path.of("p3dx.p"), p, 1);
    }

    static Obstacle box(double x0, double y0, double x1, double y1) {
        return new Obstacle(new double[] {x0, y0, x1, y0, x1, y1, x0, y1}, 500, 1);
    }

    /**
     * A world with heat sources and noise. Its Pioneers' motors are enabled ({@code motors="enabled"}),
     * as the tests of motion push their commands straight into the simulation.
     */
    static World world(double w, double h, List<Obstacle> obstacles, List<robosim.env.world.HeatSource> heat,
                       robosim.env.world.Noise noise, RobotSpec... robots) {
        return motorsOn(new World("test", Path.of("test.xml"), w, h, 100, new ArrayList<>(obstacles), List.of(robots),
                heat, noise));
    }

    /** A world of the given size with the given obstacles and robots, its Pioneers' motors enabled. */
    static World world(double w, double h, List<Obstacle> obstacles, RobotSpec... robots) {
        return motorsOn(new World("test", Path.of("test.xml"), w, h, 100, new ArrayList<>(obstacles),
                List.of(robots)));
    }

    /** A world as the world file says, but with {@code motors="enabled"}. */
    static World motorsOn(World w) {
        return w.withRules(w.rules().withMotorsEnabled(true));
    }
}
