package robosim.env.world.xml;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.deser.std.StdScalarDeserializer;
import java.io.IOException;

/**
 * Reads the text of an attribute, refusing a child element of the same name: Jackson would
 * otherwise take {@code <wall><x1>5</x1></wall>} for {@code <wall x1="5"/>}.
 */
final class AttributeDeserializer extends StdScalarDeserializer<String> {
    private static final long serialVersionUID = 1L;

    AttributeDeserializer() {
        super(String.class);
    }

    @Override
    public String deserialize(JsonParser p, DeserializationContext context) throws IOException {
        if (!XmlNodes.isAttribute(p)) {
            String name = p.currentName();
            throw new XmlProblem(XmlNodes.line(p), "unknown element <" + name + "> in <"
                    + XmlNodes.enclosingTag(p) + ">: " + name + " is an attribute");
        }
        return p.getText();
    }
}
