package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.hw.RobotSensorResponse;
import robosim.protocol.CameraView;
import robosim.protocol.ColorBlob;
import robosim.protocol.Command;
import robosim.protocol.PtzModel;
import robosim.protocol.RobotState;

/** ARIA's ArPTZ and ArACTS_1_2 names on a robot whose cycles the test drives. */
class ArPTZTest {
    private static void report(ArRobot robot, CameraView view) {
        robot.responded(new RobotSensorResponse(new RobotState(robot.getCounter() + 1, 100, 0, 0, 0, 0, 0, 0, 0,
                false, 0).with(CameraView.PART, view)));
    }

    @Test
    void aimsBeyondTheLimitsAreClampedAsArVcc4Clamps() {
        ArVCC4 ptz = new ArVCC4(Cycles.p3dxRobot());
        assertTrue(ptz.init());
        ptz.panTilt(150, -45);
        assertEquals(98, ptz.getPanDesired());
        assertEquals(-30, ptz.getTiltDesired());
        ptz.panRel(-300);
        assertEquals(-98, ptz.getPanDesired(), "relative to the clamped pan, then clamped");
        ptz.tiltRel(200);
        assertEquals(88, ptz.getTiltDesired());
        ptz.zoom(5000);
        assertEquals(1960, ptz.getZoom(), "before any report: the zoom asked for");
        ptz.zoomRel(-3000);
        assertEquals(0, ptz.getZoom());
    }

    @Test
    void theSonyHasItsOwnLimitsAndFieldOfView() {
        ArSonyPTZ sony = new ArSonyPTZ(Cycles.p3dxRobot());
        sony.panTilt(-100, 40);
        assertEquals(-95, sony.getPanDesired());
        assertEquals(25, sony.getTiltDesired());
        assertEquals(95, sony.getMaxPosPan());
        assertEquals(-25, sony.getMinTilt());
        assertEquals(1023, sony.getMaxZoom());
        assertEquals(48.8, sony.getFOVAtMinZoom());
        assertEquals(4.4, sony.getFOVAtMaxZoom());
        ArVCC4 vcc4 = new ArVCC4(Cycles.p3dxRobot());
        assertEquals(45, vcc4.getFOVAtMinZoom());
        assertEquals(1.97, vcc4.getFOVAtMaxZoom());
        assertEquals(90, vcc4.getMaxPanSlew());
        assertTrue(vcc4.canZoom());
    }

    @Test
    void getPanAnswersWhereTheEnvironmentSaysTheCameraIs() {
        ArRobot robot = Cycles.p3dxRobot();
        ArVCC4 ptz = new ArVCC4(robot);
        ptz.pan(40);
        report(robot, new CameraView(PtzModel.VCC4, 9, 0, 0, List.of()));
        assertEquals(9, ptz.getPan(), "still on its way at 90 deg/s");
        assertEquals(40, ptz.getPanDesired());
        ptz.reset();
        assertEquals(0, ptz.getPanDesired());
    }

    @Test
    void actsReportsTheBlobsOfAChannelLargestFirstAndRefusesBadNumbers() {
        ArRobot robot = Cycles.p3dxRobot();
        ArACTS_1_2 acts = new ArACTS_1_2();
        assertTrue(acts.openPort(robot));
        report(robot, new CameraView(PtzModel.VCC4, 0, 0, 0, List.of(new ColorBlob(1, 300, 80, 61, 70, 89, 50, 72),
                new ColorBlob(1, 20, 10, 11, 8, 12, 9, 13), new ColorBlob(3, 5, 150, 100, 149, 151, 99, 101))));
        assertEquals(2, acts.getNumBlobs(1));
        assertEquals(0, acts.getNumBlobs(2));
        assertEquals(-1, acts.getNumBlobs(33), "ARIA answers -1 outside 1..32");
        ArACTSBlob blob = new ArACTSBlob();
        assertTrue(acts.getBlob(1, 1, blob));
        assertEquals(300, blob.getArea());
        assertEquals(80, blob.getXCG());
        assertEquals(61, blob.getYCG());
        assertEquals(70, blob.getLeft());
        assertEquals(89, blob.getRight());
        assertEquals(50, blob.getTop());
        assertEquals(72, blob.getBottom());
        assertTrue(acts.getBlob(1, 2, blob));
        assertEquals(20, blob.getArea());
        assertFalse(acts.getBlob(1, 3, blob));
        assertFalse(acts.getBlob(1, 0, blob), "blob numbers start at 1");
        assertFalse(acts.getBlob(0, 1, blob));
        assertEquals(20, blob.getArea(), "a refused call fills nothing in");
        acts.invert();
        assertTrue(acts.getBlob(3, 1, blob));
        assertEquals(160 - 150, blob.getXCG(), "ArACTS.cpp's invertX: width minus x");
        assertEquals(120 - 100, blob.getYCG());
        assertEquals(160 - 149, blob.getLeft(), "each border flipped in place, as ARIA does");
        assertEquals(160 - 151, blob.getRight());
    }

    @Test
    void bindingAChannelChecksItsRules() {
        ArACTS_1_2 acts = new ArACTS_1_2();
        assertThrows(IllegalArgumentException.class, () -> acts.setChannelColor(1, "red"), "not open");
        acts.openPort(Cycles.p3dxRobot());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> acts.setChannelColor(0, "red"));
        assertTrue(e.getMessage().contains("channels are 1 to 32"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> acts.setChannelColor(2, "#gg0000"));
    }

    @Test
    void closingThePortStopsTheTrackingOnce() {
        ConnectedRobot robot = new ConnectedRobot("p3dx");
        ArACTS_1_2 acts = new ArACTS_1_2();
        assertFalse(acts.closePort(), "never opened");
        acts.openPort(robot);
        assertTrue(acts.closePort());
        assertFalse(acts.isConnected());
        assertFalse(acts.closePort(), "already closed");
        assertEquals(List.of(new Command.TrackColors(true), new Command.TrackColors(false)), robot.sent);
    }

    @Test
    void aBlobsFieldsAreSetOneByOne() {
        ArACTSBlob blob = new ArACTSBlob();
        blob.setArea(120);
        blob.setXCG(40);
        blob.setYCG(30);
        blob.setLeft(35);
        blob.setRight(45);
        blob.setTop(25);
        blob.setBottom(36);
        assertEquals(List.of(120, 40, 30, 35, 45, 25, 36), List.of(blob.getArea(), blob.getXCG(), blob.getYCG(),
                blob.getLeft(), blob.getRight(), blob.getTop(), blob.getBottom()));
    }
}
