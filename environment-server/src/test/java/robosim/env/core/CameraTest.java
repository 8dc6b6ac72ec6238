package robosim.env.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import robosim.env.world.Obstacle;
import robosim.protocol.CameraView;
import robosim.protocol.ColorBlob;
import robosim.protocol.Command;
import robosim.protocol.PtzModel;

/**
 * The pan-tilt-zoom camera and ACTS: a robot at (1000, 5000) facing +x, its lens 300 mm up at its
 * centre, and a red box 400 mm wide and 500 mm high whose near face stands 2000 mm ahead.
 */
class CameraTest {
    private static final double LENS = 300;
    private static final double DEPTH = 2000;
    private static final double HALF_WIDTH = 200;
    private static final double BOX_HEIGHT = 500;

    private static Obstacle redBox() {
        double x0 = 1000 + DEPTH;
        return new Obstacle(new double[] {x0, 5000 - HALF_WIDTH, x0 + 300, 5000 - HALF_WIDTH, x0 + 300,
            5000 + HALF_WIDTH, x0, 5000 + HALF_WIDTH}, BOX_HEIGHT, 1, "#ff0000");
    }

    private static Simulation sim(List<Obstacle> obstacles, PtzModel model) {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, obstacles, Worlds.robot("r", 1000, 5000, 0)));
        sim.step(Map.of("r", List.of(new Command.ConfigurePtz(model, LENS), new Command.TrackColors(true))));
        return sim;
    }

    private static CameraView aimAndWait(Simulation sim, double pan, double tilt, int zoom, int steps) {
        sim.step(Map.of("r", List.of(new Command.AimPtz(pan, tilt, zoom))));
        for (int i = 1; i < steps; i++) {
            sim.step(Map.of());
        }
        return sim.state("r").get(CameraView.PART);
    }

    /**
     * The pixels a flat face straight ahead covers, from the pinhole geometry: pixel centres on a
     * 160 × 120 image plane at unit focal distance scaled by tan(fov/2) across and 3/4 of that up;
     * the face, at depth D, spans ±HALF_WIDTH/D across and (−LENS/D, (BOX_HEIGHT − LENS)/D) up.
     *
     * @return {area, sum of columns, sum of rows}
     */
    private static long[] expectedFace(double fovDeg) {
        double across = Math.tan(Math.toRadians(fovDeg / 2));
        double up = across * 120 / 160;
        long area = 0;
        long sumX = 0;
        long sumY = 0;
        for (int u = 0; u < 160; u++) {
            double x = (u + 0.5 - 80) / 80 * across;
            if (Math.abs(x) > HALF_WIDTH / DEPTH) {
                continue;
            }
            for (int v = 0; v < 120; v++) {
                double y = (60 - (v + 0.5)) / 60 * up;
                if (y >= -LENS / DEPTH && y <= (BOX_HEIGHT - LENS) / DEPTH) {
                    area++;
                    sumX += u;
                    sumY += v;
                }
            }
        }
        return new long[] {area, sumX, sumY};
    }

    @Test
    void aRedBoxStraightAheadIsOneBlobAtTheImageCentreOfTheExpectedArea() {
        CameraView view = sim(List.of(redBox()), PtzModel.VCC4).state("r").get(CameraView.PART);
        List<ColorBlob> red = channel(view, 1);
        assertEquals(1, red.size(), "one red blob: " + view.blobs());
        long[] face = expectedFace(45);
        ColorBlob b = red.get(0);
        assertEquals(face[0], b.area(), "the face's pixels at 45°");
        assertEquals(80, b.xcg(), "centred across: columns 0..159 balance at 79.5");
        assertEquals(Math.round((double) face[2] / face[0]), b.ycg());
        assertEquals(159 - b.right(), b.left(), "symmetric about the centre");
        assertTrue(channel(view, 2).isEmpty(), "nothing green");
    }

    @Test
    void behindAWallTheBoxIsNotSeen() {
        Obstacle wall = new Obstacle(new double[] {2000, 4000, 2100, 4000, 2100, 6000, 2000, 6000}, 500, 2);
        CameraView view = sim(List.of(redBox(), wall), PtzModel.VCC4).state("r").get(CameraView.PART);
        assertEquals(List.of(), view.blobs());
    }

    @Test
    void anotherRobotInTheWayHidesTheBox() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(redBox()),
                Worlds.robot("r", 1000, 5000, 0), Worlds.robot("other", 2500, 5000, 90)));
        sim.step(Map.of("r", List.of(new Command.ConfigurePtz(PtzModel.VCC4, 200), new Command.TrackColors(true))));
        List<ColorBlob> red = channel(sim.state("r").get(CameraView.PART), 1);
        assertEquals(1, red.size(), "the box shows above the robot in the way");
        assertTrue(red.get(0).bottom() < 60,
                "only the part above the robot's 250 mm shows, above the lens at 200 mm: " + red.get(0));
    }

    @Test
    void panningRightMovesTheBlobLeftAtTheCamerasSpeed() {
        Simulation sim = sim(List.of(redBox()), PtzModel.VCC4);
        CameraView first = aimAndWait(sim, 20, 0, 0, 1);
        assertEquals(PtzModel.VCC4.panSpeed() * 0.1, first.pan(), 1e-9, "one 100 ms step at 90 deg/s");
        CameraView view = aimAndWait(sim, 20, 0, 0, 3);
        assertEquals(20, view.pan(), 1e-9);
        ColorBlob b = channel(view, 1).get(0);
        assertTrue(b.xcg() < 80 - 20, "ARIA's + pans right, so the box is now left of centre: " + b);
        CameraView left = aimAndWait(sim, -15, 0, 0, 5);
        assertTrue(channel(left, 1).get(0).xcg() > 80 + 20, "panning left moves it right");
    }

    @Test
    void zoomingNarrowsTheFieldOfViewAndEnlargesTheBlob() {
        Simulation sim = sim(List.of(redBox()), PtzModel.VCC4);
        int wideArea = channel(sim.state("r").get(CameraView.PART), 1).get(0).area();
        double fov = PtzModel.VCC4.fieldOfView(100);
        assertTrue(fov < 45 && fov > PtzModel.VCC4.fovAtMaxZoom(), "fov " + fov);
        CameraView zoomed = aimAndWait(sim, 0, 0, 100, 1);
        assertEquals(100, zoomed.zoom());
        ColorBlob b = channel(zoomed, 1).get(0);
        assertEquals(expectedFace(fov)[0], b.area());
        assertTrue(b.area() > wideArea, b.area() + " > " + wideArea);
        assertEquals(fov, sim.snapshot().robots().get(0).camera()[1], 1e-12, "viewers draw the narrower view");
    }

    @Test
    void theFieldOfViewRunsFromAriasWidestToItsNarrowest() {
        assertEquals(45, PtzModel.VCC4.fieldOfView(0), 1e-9);
        assertEquals(1.97, PtzModel.VCC4.fieldOfView(1960), 1e-9);
        assertEquals(48.8, PtzModel.SONY.fieldOfView(0), 1e-9);
        assertEquals(4.4, PtzModel.SONY.fieldOfView(5000), 1e-9, "clamped to 1023");
    }

    @Test
    void aimsBeyondTheLimitsAreClampedAsAriaClampsThem() {
        CameraView vcc4 = aimAndWait(sim(List.of(), PtzModel.VCC4), 500, -500, 99999, 20);
        assertEquals(98, vcc4.pan(), "ArVCC4.h's MAX_PAN");
        assertEquals(-30, vcc4.tilt());
        assertEquals(1960, vcc4.zoom());
        CameraView vcc4Low = aimAndWait(sim(List.of(), PtzModel.VCC4), -500, 500, -7, 20);
        assertEquals(-98, vcc4Low.pan());
        assertEquals(88, vcc4Low.tilt());
        assertEquals(0, vcc4Low.zoom());
        CameraView sony = aimAndWait(sim(List.of(), PtzModel.SONY), 500, -500, 99999, 20);
        assertEquals(95, sony.pan());
        assertEquals(-25, sony.tilt());
        assertEquals(1023, sony.zoom());
    }

    @Test
    void aChannelBoundToAnotherColourSeesTheBoxThere() {
        Simulation sim = sim(List.of(redBox()), PtzModel.VCC4);
        sim.step(Map.of("r", List.of(new Command.BindChannel(1, null), new Command.BindChannel(12, "RED"))));
        CameraView view = sim.state("r").get(CameraView.PART);
        assertTrue(channel(view, 1).isEmpty(), "channel 1 freed");
        assertEquals(expectedFace(45)[0], channel(view, 12).get(0).area());
    }

    @Test
    void aRobotThatNeverSwitchedItsCameraOnReportsNone() {
        Simulation sim = new Simulation(Worlds.world(10000, 10000, List.of(redBox()), Worlds.robot("r", 1000, 5000, 0)));
        sim.step(Map.of());
        assertNull(sim.state("r").get(CameraView.PART));
        assertNull(sim.snapshot().robots().get(0).camera(), "nothing for viewers to draw");
    }

    private static List<ColorBlob> channel(CameraView view, int channel) {
        List<ColorBlob> out = new ArrayList<>();
        for (ColorBlob b : view.blobs()) {
            if (b.channel() == channel) {
                out.add(b);
            }
        }
        return out;
    }
}
