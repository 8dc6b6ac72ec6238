package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.CameraView;
import robosim.protocol.Command;
import robosim.protocol.PtzModel;

/**
 * ArPTZ's names for a camera's limits and speeds (ARIA's ArPTZ.h, with ArVCC4.h's and ArSonyPTZ's
 * figures), its type names, relative pan-and-tilt, the field of view at the reported zoom, and the
 * mount height it is switched on with.
 */
class ArPTZLimitsTest {
    private final ConnectedRobot robot = new ConnectedRobot("p3dx");

    @Test
    void theVcc4sLimitsUnderEveryName() {
        ArVCC4 vcc4 = new ArVCC4(robot);
        assertEquals("vcc4", vcc4.getTypeName());
        assertSame(PtzModel.VCC4, vcc4.getModel());
        assertEquals(-98, vcc4.getMaxNegPan());
        assertEquals(98, vcc4.getMaxPan());
        assertEquals(-98, vcc4.getMinPan());
        assertEquals(88, vcc4.getMaxPosTilt());
        assertEquals(88, vcc4.getMaxTilt());
        assertEquals(-30, vcc4.getMaxNegTilt());
        assertEquals(0, vcc4.getMinZoom());
        assertEquals(90, vcc4.getMaxPanSpeed());
        assertEquals(69, vcc4.getMaxTiltSpeed());
        assertEquals(69, vcc4.getMaxTiltSlew());
        assertTrue(vcc4.canGetFOV());
    }

    @Test
    void theSonyNamesItself() {
        ArSonyPTZ sony = new ArSonyPTZ(robot);
        assertEquals("sony", sony.getTypeName());
        assertEquals(95, sony.getMaxPan());
        assertEquals(80, sony.getMaxPanSpeed());
        assertEquals(50, sony.getMaxTiltSpeed());
    }

    @Test
    void panTiltRelCountsFromTheLastAimAskedForAndIsClamped() {
        ArVCC4 vcc4 = new ArVCC4(robot);
        vcc4.panTilt(10, 20);
        assertTrue(vcc4.panTiltRel(-30, 80));
        assertEquals(-20, vcc4.getPanDesired());
        assertEquals(88, vcc4.getTiltDesired(), "clamped to the highest tilt");
        assertEquals(new Command.AimPtz(-20, 88, 0), robot.last());
    }

    @Test
    void theTiltAndTheFieldOfViewAreWhereTheEnvironmentLastReportedTheCamera() {
        ArVCC4 vcc4 = new ArVCC4(robot);
        vcc4.tilt(40);
        assertEquals(40, vcc4.getTilt(), "before any report: the tilt asked for");
        assertEquals(45, vcc4.getFOV(), 1e-9, "the widest zoom's field of view");
        robot.cycle(null, null, new CameraView(PtzModel.VCC4, 0, 15, 1960, List.of()));
        assertEquals(15, vcc4.getTilt(), "still on its way");
        assertEquals(1.97, vcc4.getFOV(), 1e-9, "the narrowest zoom's field of view");
        robot.cycle(null, null, new CameraView(PtzModel.VCC4, 0, 15, 980, List.of()));
        double half = vcc4.getFOV();
        assertTrue(half > 1.97 && half < 45, "between the two: " + half);
    }

    @Test
    void theMountHeightGoesWithTheSwitchOnAndMustBeAboveTheFloor() {
        ArVCC4 vcc4 = new ArVCC4(robot);
        vcc4.init();
        assertEquals(new Command.ConfigurePtz(PtzModel.VCC4, ArPTZ.DEFAULT_MOUNT_HEIGHT), robot.last());
        vcc4.setMountHeight(450);
        vcc4.init();
        assertEquals(new Command.ConfigurePtz(PtzModel.VCC4, 450), robot.last());
        assertThrows(IllegalArgumentException.class, () -> vcc4.setMountHeight(0));
        assertThrows(IllegalArgumentException.class, () -> vcc4.setMountHeight(Double.NaN));
    }
}
