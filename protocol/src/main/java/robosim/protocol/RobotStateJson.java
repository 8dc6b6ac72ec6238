package robosim.protocol;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.DeserializationContext;
import com.fasterxml.jackson.databind.JavaType;
import com.fasterxml.jackson.databind.JsonDeserializer;
import com.fasterxml.jackson.databind.JsonMappingException;
import com.fasterxml.jackson.databind.SerializerProvider;
import com.fasterxml.jackson.databind.deser.ResolvableDeserializer;
import com.fasterxml.jackson.databind.deser.std.StdDeserializer;
import com.fasterxml.jackson.databind.ser.std.StdSerializer;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

/**
 * A {@link RobotState} on the wire: one object with its fields by name ({@code step},
 * {@code timeMs}, {@code x}, ..., {@code motorsEnabled} when known), then each part it holds under
 * the part's name, in the order of {@link StateParts#ALL}. A part absent is not written; a field
 * that names no field and no registered part is refused, as every message's unknown fields are.
 */
public final class RobotStateJson {
    private RobotStateJson() {
    }

    /** Writes a state. */
    public static final class Writer extends StdSerializer<RobotState> {
        /** The serializer Jackson makes from the state's annotation. */
        public Writer() {
            super(RobotState.class);
        }

        @Override
        public void serialize(RobotState s, JsonGenerator g, SerializerProvider provider) throws IOException {
            g.writeStartObject(s);
            g.writeNumberField("step", s.step());
            g.writeNumberField("timeMs", s.timeMs());
            g.writeNumberField("x", s.x());
            g.writeNumberField("y", s.y());
            g.writeNumberField("th", s.th());
            g.writeNumberField("vel", s.vel());
            g.writeNumberField("rotVel", s.rotVel());
            g.writeNumberField("leftVel", s.leftVel());
            g.writeNumberField("rightVel", s.rightVel());
            g.writeBooleanField("stalled", s.stalled());
            g.writeNumberField("collisions", s.collisions());
            provider.defaultSerializeField("messages", s.messages(), g);
            provider.defaultSerializeField("errors", s.errors(), g);
            if (s.motorsEnabled() != null) {
                g.writeBooleanField("motorsEnabled", s.motorsEnabled());
            }
            for (StatePart<?> part : StateParts.ALL) {
                Object v = s.parts().get(part);
                if (v != null) {
                    provider.defaultSerializeField(part.name(), v, g);
                }
            }
            g.writeEndObject();
        }
    }

    /** Reads a state, with the deserializers of its lists and parts found once. */
    public static final class Reader extends StdDeserializer<RobotState> implements ResolvableDeserializer {
        private JsonDeserializer<Object> messagesReader;
        private JsonDeserializer<Object> errorsReader;
        private final List<JsonDeserializer<Object>> partReaders = new ArrayList<>();

        /** The deserializer Jackson makes from the state's annotation. */
        public Reader() {
            super(RobotState.class);
        }

        @Override
        public void resolve(DeserializationContext ctxt) throws JsonMappingException {
            messagesReader = ctxt.findRootValueDeserializer(listOf(ctxt, MessageDelivery.class));
            errorsReader = ctxt.findRootValueDeserializer(listOf(ctxt, String.class));
            for (StatePart<?> part : StateParts.ALL) {
                partReaders.add(ctxt.findRootValueDeserializer(ctxt.constructType(part.type())));
            }
        }

        @Override
        public RobotState deserialize(JsonParser p, DeserializationContext ctxt) throws IOException {
            if (!p.isExpectedStartObjectToken()) {
                return (RobotState) ctxt.handleUnexpectedToken(RobotState.class, p);
            }
            long step = 0;
            long timeMs = 0;
            double x = 0;
            double y = 0;
            double th = 0;
            double vel = 0;
            double rotVel = 0;
            double leftVel = 0;
            double rightVel = 0;
            boolean stalled = false;
            int collisions = 0;
            List<MessageDelivery> messages = List.of();
            List<String> errors = List.of();
            Boolean motorsEnabled = null;
            Object[] parts = null;
            for (String f = p.nextFieldName(); f != null; f = p.nextFieldName()) {
                p.nextToken();
                switch (f) {
                    case "step" -> step = _parseLongPrimitive(p, ctxt);
                    case "timeMs" -> timeMs = _parseLongPrimitive(p, ctxt);
                    case "x" -> x = _parseDoublePrimitive(p, ctxt);
                    case "y" -> y = _parseDoublePrimitive(p, ctxt);
                    case "th" -> th = _parseDoublePrimitive(p, ctxt);
                    case "vel" -> vel = _parseDoublePrimitive(p, ctxt);
                    case "rotVel" -> rotVel = _parseDoublePrimitive(p, ctxt);
                    case "leftVel" -> leftVel = _parseDoublePrimitive(p, ctxt);
                    case "rightVel" -> rightVel = _parseDoublePrimitive(p, ctxt);
                    case "stalled" -> stalled = _parseBooleanPrimitive(p, ctxt);
                    case "collisions" -> collisions = _parseIntPrimitive(p, ctxt);
                    case "messages" -> messages = list(p, ctxt, messagesReader, MessageDelivery.class);
                    case "errors" -> errors = list(p, ctxt, errorsReader, String.class);
                    case "motorsEnabled" -> motorsEnabled = p.currentToken() == JsonToken.VALUE_NULL ? null
                            : _parseBooleanPrimitive(p, ctxt);
                    default -> parts = part(p, ctxt, f, parts);
                }
            }
            return new RobotState(step, timeMs, x, y, th, vel, rotVel, leftVel, rightVel, stalled, collisions,
                    messages, errors, motorsEnabled, parts == null ? StateParts.NONE : StateParts.ofValues(parts));
        }

        @SuppressWarnings("unchecked")
        private static <T> List<T> list(JsonParser p, DeserializationContext ctxt, JsonDeserializer<Object> reader,
                                        Class<T> element) throws IOException {
            return p.currentToken() == JsonToken.VALUE_NULL ? List.of() : (List<T>) reader.deserialize(p, ctxt);
        }

        /** Reads a part into its place, or refuses a field that names none. */
        private Object[] part(JsonParser p, DeserializationContext ctxt, String name, Object[] parts)
                throws IOException {
            int i = StateParts.indexNamed(name);
            if (i < 0) {
                ctxt.handleUnknownProperty(p, this, RobotState.class, name);
                return parts;
            }
            Object[] out = parts == null ? new Object[StateParts.ALL.size()] : parts;
            out[i] = p.currentToken() == JsonToken.VALUE_NULL ? null : partReaders.get(i).deserialize(p, ctxt);
            return out;
        }

        private static JavaType listOf(DeserializationContext ctxt, Class<?> element) {
            return ctxt.getTypeFactory().constructCollectionType(List.class, element);
        }
    }
}
