package robosim.scout;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/** The static facade with no robot connected: every call is FALSE, as the C library's. */
class NomadTest {
    @Test
    void everyCallIsFalseWithoutARobot() {
        assertNull(Nomad.robot());
        assertFalse(Nomad.gs());
        assertFalse(Nomad.get_sn());
        assertFalse(Nomad.get_bp());
        assertFalse(Nomad.get_rc());
        assertFalse(Nomad.get_rv());
        assertFalse(Nomad.vm(10, 10, 0));
        assertFalse(Nomad.scout_vm(10, 0));
        assertFalse(Nomad.pr(10, 10, 0));
        assertFalse(Nomad.ac(10, 10, 0));
        assertFalse(Nomad.sp(10, 10, 0));
        assertFalse(Nomad.st());
        assertFalse(Nomad.lp());
        assertFalse(Nomad.ws(1, 1, 0, 1));
        assertFalse(Nomad.conf_tm(1));
        assertFalse(Nomad.zr());
        assertFalse(Nomad.dp(0, 0));
        assertFalse(Nomad.da(0, 0));
        assertFalse(Nomad.conf_sn(10, new int[] {0}));
        assertFalse(Nomad.tk("hello"));
        assertFalse(Nomad.report_metric("cells", 1));
        assertFalse(Nomad.end_run("done"));
        assertFalse(Nomad.disconnect_robot(1));
        assertFalse(Nomad.disconnect_robot("s1"));
    }

    @Test
    void unsupportedCallsAreFalse() {
        assertFalse(Nomad.pa(0, 0, 0));
        assertFalse(Nomad.conf_ir(0, new int[] {255}));
        assertFalse(Nomad.conf_cp(1));
    }

    @Test
    void theStateVectorHas45Entries() {
        assertEquals(StateVector.NUM_STATE, Nomad.State.length);
    }
}
