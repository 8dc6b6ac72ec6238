package robosim.aria;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** ARIA's ArTransform: the rigid motion that carries one pose onto another, and its inverse. */
class ArTransformTest {
    private static void assertPose(double x, double y, double th, ArPose p) {
        assertEquals(x, p.getX(), 1e-9, "x of " + p);
        assertEquals(y, p.getY(), 1e-9, "y of " + p);
        assertEquals(th, p.getTh(), 1e-9, "th of " + p);
    }

    @Test
    void itCarriesTheFirstPoseOntoTheSecond() {
        ArPose from = new ArPose(100, 200, 30);
        ArPose to = new ArPose(-50, 400, 120);
        ArTransform t = new ArTransform(from, to);
        assertEquals(90, t.getTh(), 1e-9);
        assertPose(-50, 400, 120, t.doTransform(from));
    }

    @Test
    void aPoseAheadOfTheFirstEndsAheadOfTheSecond() {
        ArTransform t = new ArTransform(new ArPose(0, 0, 0), new ArPose(1000, 1000, 90));
        assertPose(1000, 1100, 90, t.doTransform(new ArPose(100, 0, 0)));
    }

    @Test
    void theInverseUndoesIt() {
        ArTransform t = new ArTransform(new ArPose(100, 200, 30), new ArPose(-50, 400, -170));
        ArPose p = new ArPose(321, -45, 12);
        ArPose back = t.doInvTransform(t.doTransform(p));
        assertPose(321, -45, 12, back);
        assertPose(100, 200, 30, t.doInvTransform(new ArPose(-50, 400, -170)));
    }

    @Test
    void theIdentityLeavesEveryPoseWhereItIs() {
        ArTransform identity = new ArTransform();
        assertPose(5, -7, 45, identity.doTransform(new ArPose(5, -7, 45)));
        assertPose(5, -7, 45, identity.doInvTransform(new ArPose(5, -7, 45)));
    }
}
