package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import robosim.protocol.CameraView;
import robosim.protocol.ColorBlob;
import robosim.protocol.PtzModel;

/** ArActionColorFollow.cpp's rules (ARIA 2.x): the largest blob steers; lost, it turns to the side last seen. */
class ArActionColorFollowTest {
    private final ConnectedRobot robot = new ConnectedRobot("p3dx");
    private final ArACTS_1_2 acts = new ArACTS_1_2();
    private final ArActionColorFollow follow = new ArActionColorFollow("follow", acts, null);

    ArActionColorFollowTest() {
        acts.openPort(robot);
        follow.setRobot(robot);
    }

    private void sees(ColorBlob... blobs) {
        robot.cycle(null, null, new CameraView(PtzModel.VCC4, 0, 0, 0, List.of(blobs)));
    }

    private static ColorBlob blob(int channel, int area, int xcg, int ycg) {
        return new ColorBlob(channel, area, xcg, ycg, xcg - 5, xcg + 5, ycg - 5, ycg + 5);
    }

    @Test
    void withMovementStoppedItHoldsTheRobotStill() {
        sees(blob(1, 400, 140, 60));
        ArActionDesired d = ActionFixture.fire(follow);
        assertEquals(0, d.getVel());
        assertEquals(0, d.getDeltaHeading());
        assertTrue(follow.getBlob());
    }

    @Test
    void theLargestBlobOnItsChannelSteersAtTenTimesItsOffset() {
        follow.startMovement();
        sees(blob(1, 30, 20, 60), blob(1, 400, 140, 60), blob(2, 900, 80, 60));
        ArActionDesired d = ActionFixture.fire(follow);
        assertEquals(200, d.getVel());
        assertEquals(-10 * (140 - 80) / 160.0, d.getDeltaHeading(), 1e-9, "right of centre: turn right");
    }

    @Test
    void aCentredBlobIsDrivenStraightAt() {
        follow.startMovement();
        sees(blob(1, 400, 85, 60));
        ArActionDesired d = ActionFixture.fire(follow);
        assertEquals(200, d.getVel());
        assertEquals(0, d.getDeltaHeading());
    }

    @Test
    void aBlobLostForAMomentIsLookedForOnTheSideItWasLastOn() {
        follow.startMovement();
        sees(blob(1, 400, 10, 60));
        assertTrue(ActionFixture.fire(follow).getDeltaHeading() > 0);
        sees();
        ArActionDesired d = ActionFixture.fire(follow);
        assertEquals(0, d.getVel());
        assertEquals(10, d.getDeltaHeading());
    }

    @Test
    void withNoTargetForTwoSecondsItTurnsInPlaceToAcquireOne() {
        follow.startMovement();
        sees(blob(1, 400, 80, 60));
        ActionFixture.fire(follow);
        for (int i = 0; i < 25; i++) {
            sees();
        }
        ArActionDesired d = ActionFixture.fire(follow);
        assertFalse(follow.getBlob());
        assertEquals(0, d.getVel());
        assertEquals(8, d.getDeltaHeading());
        follow.setAcquire(false);
        assertEquals(0, ActionFixture.fire(follow).getDeltaHeading(), "not acquiring: still");
    }

    @Test
    void blobsOfTwentyPixelsOrLessAreNotFollowed() {
        follow.startMovement();
        sees(blob(1, 20, 150, 60));
        ArActionDesired d = ActionFixture.fire(follow);
        assertEquals(200, d.getVel(), "a target (seen), but no blob to steer by: on from the centre");
        assertEquals(0, d.getDeltaHeading());
        assertFalse(follow.setChannel(0));
        assertEquals(1, follow.getChannel());
    }

    @Test
    void theGroupGuardsTheFollower() {
        ArActionGroupColorFollow group = new ArActionGroupColorFollow(robot, acts, null);
        assertEquals(List.of(100, 90, 89, 80, 70),
                robot.getActionList().stream().map(ArResolver.Entry::priority).toList());
        assertFalse(group.getMovement());
        group.startMovement();
        assertTrue(group.getMovement());
        group.setChannel(3);
        assertEquals(3, group.getChannel());
    }
}
