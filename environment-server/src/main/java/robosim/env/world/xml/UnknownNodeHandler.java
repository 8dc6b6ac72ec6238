package robosim.env.world.xml;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.JsonDeserializer;
import com.fasterxml.jackson.databind.deser.DeserializationProblemHandler;
import java.io.IOException;
import robosim.protocol.LogLimiter;

/** Turns a field Jackson does not know into an unknown element, attribute or stray text. */
final class UnknownNodeHandler extends DeserializationProblemHandler {

    @Override
    public boolean handleUnknownProperty(DeserializationContext context, JsonParser p,
                                         JsonDeserializer<?> deserializer, Object bean, String name)
            throws IOException {
        String tag = bean instanceof Element e ? e.tag() : XmlNodes.enclosingTag(p);
        int line = XmlNodes.line(p);
        if (name.isEmpty()) {
            throw new XmlProblem(line, "unexpected text in <" + tag + ">: <" + tag + "> takes only attributes"
                    + (tag.equals("world") ? " and child elements" : ""));
        }
        if (XmlNodes.isAttribute(p)) {
            throw new XmlProblem(line, "unknown attribute " + LogLimiter.excerpt(name) + " on <" + tag + ">");
        }
        throw new XmlProblem(line, "unknown element <" + LogLimiter.excerpt(name) + "> in <" + tag + ">");
    }
}
