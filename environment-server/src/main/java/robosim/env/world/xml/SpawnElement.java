package robosim.env.world.xml;

import com.fasterxml.jackson.dataformat.xml.annotation.JacksonXmlProperty;

/** A {@code <spawn>} element: a pose where an open world places a robot it does not name. */
final class SpawnElement extends Element {
    @JacksonXmlProperty(isAttribute = true)
    String x;
    @JacksonXmlProperty(isAttribute = true)
    String y;
    @JacksonXmlProperty(isAttribute = true)
    String th;

    @Override
    String tag() {
        return "spawn";
    }
}
