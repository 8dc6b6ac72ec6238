/**
 * How the parts of a robot's state travel in a Pioneer's standard status packet (SIP), both ways:
 * the Pioneer ports write them for an ARIA program, and RoboSim's own Pioneer link reads them back
 * from a Pioneer robot server. Each part that a SIP carries has one {@link robosim.hw.sip.SipPart},
 * registered in {@link robosim.hw.sip.SipParts#ALL}.
 */
package robosim.hw.sip;
