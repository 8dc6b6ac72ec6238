package robosim.viewer.draw;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import robosim.protocol.Snapshot.RobotView;

/**
 * The dashed ghost of a robot's body where its odometry puts it. The robot stands at (3000, 600) mm,
 * pixel (600, 280); a ghost at (2000, 1500) mm is centred on pixel (400, 100) and spans pixels
 * 360..440 by 62..138.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class OdometryGhostTest {
    private final WorldRenderer renderer = new WorldRenderer();

    private BufferedImage render(RobotView robot, boolean odometry) {
        RenderOptions options = new RenderOptions(Fixtures.WIDTH_PX, false, false).withOdometry(odometry);
        return renderer.render(Fixtures.world(), Fixtures.snapshot(1, robot), options);
    }

    private static RobotView believing(double odoX, double odoY, double odoTh) {
        return Fixtures.robot(3000, 600, 0, odoX, odoY, odoTh, new int[0], 1);
    }

    @Test
    void ghostAppearsWhereTheOdometrySays() {
        BufferedImage exact = render(Fixtures.robotAtRest(), true);
        BufferedImage drifted = render(believing(2000, 1500, 0), true);
        assertTrue(Pixels.differing(exact, drifted, 355, 55, 445, 145) > 100, "the ghost's outline");
        assertEquals(WorldRenderer.BACKGROUND, Pixels.at(drifted, 380, 100), "an outline, not a filled body");
        assertEquals(0, Pixels.differing(exact, drifted, 500, 200, 800, 400), "the real robot is unchanged");
    }

    @Test
    void ghostIsDashed() {
        BufferedImage drifted = render(believing(2000, 1500, 0), true);
        // The rear edge runs down pixel column 360 from row 62 to 138: dashes leave gaps.
        int drawn = 0;
        for (int y = 66; y < 134; y++) {
            drawn += Pixels.at(drifted, 360, y).equals(WorldRenderer.BACKGROUND) ? 0 : 1;
        }
        assertTrue(drawn > 20 && drawn < 60, drawn + " of 68 pixels drawn");
    }

    @Test
    void noGhostWhenTheOdometryIsTheTruePose() {
        // the world only: the legend below it explains the ghost when ghosts are shown
        assertEquals(0, Pixels.differing(render(Fixtures.robotAtRest(), true), render(Fixtures.robotAtRest(), false),
                0, 0, 800, 400));
    }

    @Test
    void noGhostWithinOneMillimetreAndHalfADegree() {
        BufferedImage exact = render(Fixtures.robotAtRest(), true);
        assertEquals(0, Pixels.differing(exact, render(believing(3000.7, 600.5, 0.4), true)));
    }

    @Test
    void ghostOfAHeadingErrorAlone() {
        BufferedImage exact = render(Fixtures.robotAtRest(), true);
        assertTrue(Pixels.differing(exact, render(believing(3000, 600, 10), true), 540, 220, 660, 340) > 20);
    }

    @Test
    void noGhostWhenShowOdometryIsOff() {
        assertEquals(0, Pixels.differing(render(Fixtures.robotAtRest(), false), render(believing(2000, 1500, 0), false)));
    }

    @ParameterizedTest
    @CsvSource({
        "3000,   600,   0,      false",
        "3001,   600,   0,      false",
        "3001.1, 600,   0,      true",
        "3000,   598.9, 0,      true",
        "3000,   600,   0.5,    false",
        "3000,   600,   0.51,   true",
        "3000,   600,   -0.51,  true",
        "3000,   600,   359.8,  false",
        "3000,   600,   NaN,    false"})
    void odometryDiffersBeyondOneMillimetreOrHalfADegree(double odoX, double odoY, double odoTh, boolean differs) {
        assertEquals(differs, RobotPainter.odometryDiffers(believing(odoX, odoY, odoTh)));
    }

    @Test
    void threeArgumentOptionsShowLaserAndOdometry() {
        RenderOptions options = new RenderOptions(400, false, true);
        assertEquals(new RenderOptions(400, false, true, true, true), options);
        assertEquals(List.of(false, false), List.of(options.withLaser(false).showLaser(),
                options.withOdometry(false).showOdometry()));
    }
}
