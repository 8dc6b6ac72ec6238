package robosim.protocol;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

/**
 * Every message that crosses the wire between the Environment and its robots and viewers. One
 * message is one frame (see {@link FrameReader}); the {@code type} property names the kind.
 *
 * <p>The type names are the wire format and do not follow renames in the code: a {@link Snapshot}
 * is still sent as {@code frame}, its first name, so that recordings and viewers made before it was
 * renamed keep working.
 */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, property = "type")
@JsonSubTypes({
        @JsonSubTypes.Type(value = RobotHello.class, name = "robotHello"),
        @JsonSubTypes.Type(value = Welcome.class, name = "welcome"),
        @JsonSubTypes.Type(value = TimeStep.class, name = "timeStep"),
        @JsonSubTypes.Type(value = RobotRequests.class, name = "robotRequests"),
        @JsonSubTypes.Type(value = ViewerHello.class, name = "viewerHello"),
        @JsonSubTypes.Type(value = WorldDescription.class, name = "world"),
        @JsonSubTypes.Type(value = Snapshot.class, name = "frame"),
        @JsonSubTypes.Type(value = Bye.class, name = "bye"),
        @JsonSubTypes.Type(value = CommsUpdate.class, name = "commsUpdate"),
        @JsonSubTypes.Type(value = LinkHello.class, name = "linkHello"),
        @JsonSubTypes.Type(value = TimeSteps.class, name = "timeSteps"),
        @JsonSubTypes.Type(value = LinkRequests.class, name = "linkRequests"),
        @JsonSubTypes.Type(value = ControlHello.class, name = "controlHello"),
        @JsonSubTypes.Type(value = KeepAlive.class, name = "keepAlive"),
        @JsonSubTypes.Type(value = ControlRequest.class, name = "controlRequest"),
        @JsonSubTypes.Type(value = ControlReply.class, name = "controlReply"),
        @JsonSubTypes.Type(value = RunStatus.class, name = "runStatus"),
        @JsonSubTypes.Type(value = LogLine.class, name = "logLine"),
})
public sealed interface Message
        permits RobotHello, Welcome, TimeStep, RobotRequests, ViewerHello, WorldDescription, Snapshot, Bye,
        CommsUpdate, LinkHello, TimeSteps, LinkRequests, ControlHello, KeepAlive,
        ControlRequest, ControlReply, RunStatus, LogLine {
}
