package robosim.hw.sip;

import java.util.Arrays;
import robosim.params.ConversionFactors;
import robosim.pioneer.Sip;
import robosim.protocol.RobotState;
import robosim.protocol.SonarReading;
import robosim.protocol.StateParts;

/**
 * The sonar ring in SIPs, ranges divided by the RangeConvFactor. While the SIP's flags say the
 * sonars are on, a SIP carries at most {@value #MAX_PER_SIP} readings, cycling through the ring as
 * MobileSim does, so a ring of more than 16 takes several SIPs; the reading side keeps the whole
 * ring, each SIP updating the transducers it carries.
 */
final class SonarInSip implements SipPart {
    /** The most sonar readings one SIP carries. */
    static final int MAX_PER_SIP = 16;
    private static final int[] NONE = new int[0];

    private final ConversionFactors factors;
    private final int[] ring;
    private int next;

    SonarInSip(SipContext context) {
        this.factors = context.factors();
        this.ring = new int[context.sonarCount()];
        Arrays.fill(ring, (int) Math.round(context.sonarMaxRange()));
    }

    @Override
    public void write(RobotState state, SipFields sip) {
        int[] ranges = state.get(SonarReading.PART).ranges();
        if ((sip.flags & Sip.FLAG_SONARS) == 0 || ranges.length == 0) {
            return;
        }
        if (next >= ranges.length) {
            next = 0;
        }
        int n = Math.min(MAX_PER_SIP, ranges.length - next);
        for (int i = next; i < next + n; i++) {
            sip.sonar.add(new Sip.SonarReading(i, (int) Math.round(ranges[i] / factors.rangeConvFactor())));
        }
        next = (next + n) % ranges.length;
    }

    @Override
    public StateParts read(Sip sip, StateParts parts) {
        for (Sip.SonarReading r : sip.sonar()) {
            if (r.index() < ring.length) {
                ring[r.index()] = (int) Math.round(r.range() * factors.rangeConvFactor());
            }
        }
        int[] ranges = (sip.flags() & Sip.FLAG_SONARS) != 0 ? ring.clone() : NONE;
        return parts.with(SonarReading.PART, ranges.length == 0 ? null : new SonarReading(ranges));
    }
}
