package robosim.aria;

import java.util.Collections;
import java.util.Map;
import java.util.TreeMap;
import robosim.aria.ArRobot.ChargeState;
import robosim.params.BumperParameters;
import robosim.params.ConversionFactors;
import robosim.params.RobotParameterFiles;
import robosim.protocol.Command;
import robosim.protocol.RobotParameters;
import robosim.protocol.RobotState;

/**
 * {@link ArRobot}'s body and devices: its parameters and parameter file, stall and bumpers, battery,
 * flags, IO, charge and temperature (as far as the simulation has them), motors, wheel encoders and
 * sonar, as ARIA's {@code ArRobot} has them (ArRobot.cpp, ArRobot.h). One of the package-private
 * layers that {@link ArRobot}, the public face, is made of.
 */
abstract class ArRobotDevices extends ArRobotCycle {
    /** The sonar ring the parameters give, with its latest readings. */
    volatile SonarRing sonar;
    private volatile boolean sonarEnabled = true;
    private volatile boolean autonomousDrivingSonar;
    /** ARIA's sonar boards ({@code addSonar}), by number. */
    final Map<Integer, ArRangeDevice> sonarBoards = Collections.synchronizedMap(new TreeMap<>());
    /** The battery's readings and their averages. */
    final BatteryGauge battery = new BatteryGauge();
    /** The wheels' encoder counts, in ticks of the parameter file's {@code DistConvFactor}. */
    volatile WheelEncoders wheelEncoders = new WheelEncoders(1);
    /** The bump rings the parameter file declares. */
    volatile BumperParameters bumpers = BumperParameters.ARIA_DEFAULTS;

    /** The robot, named and placed, with its parameters: see {@link ArRobot}'s constructors. */
    ArRobotDevices(String name, String host, int port, RobotParameters parameters) {
        super(name, host, port, parameters);
    }

    /** The sonar ring the parameters give; the motion layer adds the limits. */
    void useParameters(RobotParameters parameters) {
        this.sonar = new SonarRing(parameters.sonarUnits(), parameters.sonarMaxRange());
    }

    // ---- the body and its parameter file ----

    /** @return the radius of the circle enclosing the robot, mm */
    public double getRobotRadius() {
        return getParameters().robotRadius();
    }

    /** @return the robot's width, mm */
    public double getRobotWidth() {
        return getParameters().robotWidth();
    }

    /** @return the robot's length, mm */
    public double getRobotLength() {
        return getParameters().robotLength();
    }

    /** @return the robot's length ahead of its centre, mm */
    public double getRobotLengthFront() {
        return getParameters().robotLengthFront();
    }

    /** @return the robot's length behind its centre, mm */
    public double getRobotLengthRear() {
        return getParameters().robotLengthRear();
    }

    /** @return ARIA's {@code RobotDiagonal} default, 120 mm (RoboSim's parameters do not carry the key) */
    public double getRobotDiagonal() {
        return 120;
    }

    /**
     * @return the robot's parameters, the values its parameter file gave (ARIA's {@code ArRobotParams}:
     *         size, speeds, accelerations, sonar units, laser mount)
     */
    public RobotParameters getRobotParams() {
        return getParameters();
    }

    /**
     * Gives the robot other parameters before it connects, as ARIA's {@code ArRobot::setRobotParams}
     * (ArRobot.cpp); once it is connected the Environment has its body, so they are refused with a log
     * line.
     *
     * @param params the parameters
     */
    public void setRobotParams(RobotParameters params) {
        if (linkConnected()) {
            LOG.warning(() -> "robot " + getName()
                    + ": setRobotParams: the robot is connected; its parameters are fixed");
            return;
        }
        relocate(getName(), getHost(), getPort(), params);
        parametersFrom(null);
    }

    /**
     * Reads a parameter file for the robot before it connects, as ARIA's {@code ArRobot::loadParamFile} (ArRobot.cpp):
     * its body, speeds, sonar units, bump rings and sonar cycle.
     *
     * @param file a path, or a shipped name such as {@code p3at}
     * @return false, with a log line, if the file cannot be read or the robot is connected
     */
    public boolean loadParamFile(String file) {
        if (linkConnected()) {
            LOG.warning(() -> "robot " + getName() + ": loadParamFile(" + file
                    + "): the robot is connected; its parameters are fixed");
            return false;
        }
        try {
            RobotParameters p = RobotParameterFiles.load(file);
            BumperParameters b = RobotParameterFiles.bumpers(file);
            int cycle = RobotParameterFiles.sonarCycle(file);
            ConversionFactors f = RobotParameterFiles.conversionFactors(file);
            relocate(getName(), getHost(), getPort(), p);
            parametersFrom(file);
            bumpers = b;
            sonarCycleMs = cycle;
            wheelEncoders = new WheelEncoders(f.distConvFactor());
            return true;
        } catch (RuntimeException e) {
            LOG.warning(() -> "robot " + getName() + ": ArRobot::loadParamFile: Could not load " + file
                    + ": " + e.getMessage());
            return false;
        }
    }

    // ---- stall and bumpers ----

    /**
     * @return whether the left motor is stalled: bit 0 of {@link #getStallValue()}, as ARIA's
     *         {@code ArRobot.h} reads it (RoboSim stalls both wheels together)
     */
    public boolean isLeftMotorStalled() {
        return (getStallValue() & StallValue.LEFT_MOTOR) != 0;
    }

    /**
     * @return whether the right motor is stalled: bit 8 of {@link #getStallValue()}, as ARIA's
     *         {@code ArRobot.h} reads it
     */
    public boolean isRightMotorStalled() {
        return (getStallValue() & StallValue.RIGHT_MOTOR) != 0;
    }

    /**
     * The Pioneer's stall and bumper flags, with ARIA's layout: bit 0 the left motor's stall, bits
     * 1–7 the rear bumpers, bit 8 the right motor's stall, bits 9–15 the front bumpers (bumper i in
     * bit 1 + i, or 9 + i). The bumper flags come from the body's six contact sectors (see
     * {@link ArBumpers} and docs/ARIA-SEMANTICS.md for the mapping); a ring the parameter file does
     * not declare reports none.
     *
     * @return the flags of the latest cycle
     */
    public int getStallValue() {
        return StallValue.of(state(), bumpers);
    }

    /** @return whether a front bumper is pressed (and the robot has a front ring), as in ARIA */
    public boolean isFrontBumperTriggered() {
        return hasFrontBumpers() && (getStallValue() >> 9 & 0x7f) != 0;
    }

    /** @return whether a rear bumper is pressed (and the robot has a rear ring), as in ARIA */
    public boolean isRearBumperTriggered() {
        return hasRearBumpers() && (getStallValue() >> 1 & 0x7f) != 0;
    }

    /** @return whether the parameter file gives the robot a front bump ring ({@code FrontBumpers}) */
    public boolean hasFrontBumpers() {
        return bumpers.frontBumpers();
    }

    /** @return the front ring's bumpers ({@code NumFrontBumpers}, ARIA's default 5) */
    public int getNumFrontBumpers() {
        return bumpers.numFrontBumpers();
    }

    /** @return whether the parameter file gives the robot a rear bump ring ({@code RearBumpers}) */
    public boolean hasRearBumpers() {
        return bumpers.rearBumpers();
    }

    /** @return the rear ring's bumpers ({@code NumRearBumpers}, ARIA's default 5) */
    public int getNumRearBumpers() {
        return bumpers.numRearBumpers();
    }

    // ---- battery ----

    /**
     * The battery voltage on ARIA's 12 V scale, averaged over the latest
     * {@link #getBatteryVoltageAverageOfNum()} readings (20), as ARIA averages its SIPs'. The
     * simulated battery is a Pioneer 3's 12 V pack: 13 V full, lower while the motors draw and the
     * longer they have driven (see docs/ARIA-API.md).
     *
     * @return volts
     */
    public double getBatteryVoltage() {
        return underLock(() -> battery.voltage());
    }

    /** @return the latest battery reading, volts, not averaged */
    public double getBatteryVoltageNow() {
        return underLock(() -> battery.voltageNow());
    }

    /** @return the real battery voltage, averaged: the same as {@link #getBatteryVoltage()} for a 12 V pack */
    public double getRealBatteryVoltage() {
        return underLock(() -> battery.realVoltage());
    }

    /**
     * @return the latest real battery voltage, volts: the same as {@link #getBatteryVoltageNow()}
     *     unless {@link #setBatteryInfo} gave another
     */
    public double getRealBatteryVoltageNow() {
        return underLock(() -> battery.realVoltageNow());
    }

    /** @return whether the robot reports its state of charge: once a reading above 0 has come */
    public boolean haveStateOfCharge() {
        return underLock(() -> battery.haveStateOfCharge());
    }

    /** @return as {@link #haveStateOfCharge()} */
    public boolean hasStateOfCharge() {
        return haveStateOfCharge();
    }

    /** @return the charge left, percent, 0 to 100; 0 when the robot does not report it */
    public double getStateOfCharge() {
        return underLock(() -> battery.stateOfCharge());
    }

    /** @return how many readings {@link #getBatteryVoltage()} averages */
    public int getBatteryVoltageAverageOfNum() {
        return underLock(() -> battery.averageOf());
    }

    /**
     * @param numToAverage how many readings {@link #getBatteryVoltage()} averages from now on
     * @throws IllegalArgumentException if less than 1
     */
    public void setBatteryVoltageAverageOfNum(int numToAverage) {
        underLock(() -> battery.setAverageOf(numToAverage));
    }

    /** @return how many readings {@link #getRealBatteryVoltage()} averages */
    public int getRealBatteryVoltageAverageOfNum() {
        return underLock(() -> battery.realAverageOf());
    }

    /**
     * @param numToAverage how many readings {@link #getRealBatteryVoltage()} averages from now on
     * @throws IllegalArgumentException if less than 1
     */
    public void setRealBatteryVoltageAverageOfNum(int numToAverage) {
        underLock(() -> battery.setRealAverageOf(numToAverage));
    }

    // ---- flags, IO, charge and temperature, as far as the simulation has them ----

    /**
     * ARIA's flags word from the latest state: bit 0 the motors enabled, bits 1–4 the sonars on
     * (ARIA's legacy sonar bits), bit 5 the e-stop (never pressed in the simulation), bit 10 the
     * charger's power (never: no charger is simulated).
     *
     * @return the flags
     */
    public int getFlags() {
        int f = areMotorsEnabled() ? 1 : 0;
        if (sonarEnabled || autonomousDrivingSonar) {
            f |= 0x1e;
        }
        return f;
    }

    /** @return 0: the simulated robot reports no faults */
    public int getFaultFlags() {
        return 0;
    }

    /** @return false: the simulated robot sends no fault flags */
    public boolean hasFaultFlags() {
        return false;
    }

    /** @return 0: the simulated robot sends no third flags word */
    public int getFlags3() {
        return 0;
    }

    /** @return false: the simulated robot sends no third flags word */
    public boolean hasFlags3() {
        return false;
    }

    /** @return whether the legacy sonar bits (1–4) of {@link #getFlags()} are set */
    public boolean areSonarsEnabledLegacy() {
        return (getFlags() & 0x1e) != 0;
    }

    /** @return false: the simulation has no e-stop (bit 5 of {@link #getFlags()}) */
    public boolean isEStopPressed() {
        return (getFlags() & 0x20) != 0;
    }

    /** @return as {@link #isEStopPressed()} */
    public boolean getEstop() {
        return isEStopPressed();
    }

    /** @return 0: no compass is simulated */
    public double getCompass() {
        return 0;
    }

    /** @return 0: no analog port is simulated */
    public int getAnalogPortSelected() {
        return 0;
    }

    /** @return 0: no analog input is simulated */
    public int getAnalog() {
        return 0;
    }

    /** @return 0: no digital inputs are simulated */
    public int getDigIn() {
        return 0;
    }

    /** @return 0: no digital outputs are simulated */
    public int getDigOut() {
        return 0;
    }

    /**
     * Asks for IO packets, as ARIA's {@code ArRobot::requestIOPackets} (ArRobot.cpp); the simulation
     * has no IO, so none come.
     */
    public void requestIOPackets() {
        extras.ioRequested = true;
    }

    /** Stops asking for IO packets. */
    public void stopIOPackets() {
        extras.ioRequested = false;
    }

    /** @return whether {@link #requestIOPackets()} was called (and not stopped) */
    public boolean haveRequestedIOPackets() {
        return extras.ioRequested;
    }

    /** @return 0: no IO packet has come, so no analog inputs are known */
    public int getIOAnalogSize() {
        return 0;
    }

    /** @return 0: no digital inputs are known */
    public int getIODigInSize() {
        return 0;
    }

    /** @return 0: no digital outputs are known */
    public int getIODigOutSize() {
        return 0;
    }

    /** @param num an analog input @return 0, as ARIA answers for an input it has no reading of */
    public int getIOAnalog(int num) {
        return 0;
    }

    /** @param num an analog input @return 0 V */
    public double getIOAnalogVoltage(int num) {
        return 0;
    }

    /** @param num a digital input bank @return 0, as ARIA answers for a bank outside the IO packet */
    public int getIODigIn(int num) {
        return 0;
    }

    /** @param num a digital output bank @return 0 */
    public int getIODigOut(int num) {
        return 0;
    }

    /** @return the time of the last IO packet: the connection's start, as none comes */
    public ArTime getIOPacketTime() {
        return timeAt(events.openedMs);
    }

    /** @return false: the parameter files give RoboSim's robots no table-sensing IR */
    public boolean hasTableSensingIR() {
        return false;
    }

    /** @return false: ARIA answers false for a robot without table-sensing IR */
    public boolean isLeftTableSensingIRTriggered() {
        return false;
    }

    /** @return false, as {@link #isLeftTableSensingIRTriggered()} */
    public boolean isRightTableSensingIRTriggered() {
        return false;
    }

    /** @return false: ARIA answers false for a robot without table-sensing IR (its break beams) */
    public boolean isLeftBreakBeamTriggered() {
        return false;
    }

    /** @return false, as {@link #isLeftBreakBeamTriggered()} */
    public boolean isRightBreakBeamTriggered() {
        return false;
    }

    /**
     * @return the charge state a program set ({@link #setChargeState}), else CHARGING_UNKNOWN: no
     *     charger is simulated
     */
    public ChargeState getChargeState() {
        ChargeState c = extras.chargeState;
        return c != null ? c : ChargeState.CHARGING_UNKNOWN;
    }

    /** @return ARIA's name of {@link #getChargeState()}: Unknown, Not, Bulk, Overcharge, Float or Balance */
    public String getChargeStateName() {
        return getChargeState().label;
    }

    /** @param chargeState the charge state {@link #getChargeState()} answers from now on (ARIA's override) */
    public void setChargeState(ChargeState chargeState) {
        extras.chargeState = chargeState;
    }

    /** @return what {@link #setIsChargerPowerGood} set, else bit 10 of {@link #getFlags()}: false */
    public boolean isChargerPowerGood() {
        Boolean b = extras.chargerPowerGood;
        return b != null ? b : (getFlags() & 0x400) != 0;
    }

    /** @param onCharger what {@link #isChargerPowerGood()} answers from now on (ARIA's override) */
    public void setIsChargerPowerGood(boolean onCharger) {
        extras.chargerPowerGood = onCharger;
    }

    /**
     * Sets the state of charge, as ARIA's {@code ArRobot::setStateOfCharge} (ArRobot.cpp): the robot has
     * one from now on; a reading with a state of charge from the Environment replaces it.
     *
     * @param stateOfCharge percent
     */
    public void setStateOfCharge(double stateOfCharge) {
        underLock(() -> battery.setStateOfCharge(stateOfCharge, simulatedMs()));
    }

    /** @return the simulated time the state of charge was last set or read (0 before) */
    public ArTime getStateOfChargeSetTime() {
        return timeAt(underLock(() -> battery.stateOfChargeSetMs()));
    }

    /** @return the state of charge below which the robot counts as low, percent (ARIA's default 0) */
    public double getStateOfChargeLow() {
        return extras.stateOfChargeLow;
    }

    /** @param stateOfChargeLow percent */
    public void setStateOfChargeLow(double stateOfChargeLow) {
        extras.stateOfChargeLow = stateOfChargeLow;
    }

    /** @return the state of charge at which the robot shuts down, percent (ARIA's default 0) */
    public double getStateOfChargeShutdown() {
        return extras.stateOfChargeShutdown;
    }

    /** @param stateOfChargeShutdown percent */
    public void setStateOfChargeShutdown(double stateOfChargeShutdown) {
        extras.stateOfChargeShutdown = stateOfChargeShutdown;
    }

    /**
     * ARIA's {@code ArRobot::setIgnoreMicroControllerBatteryInfo} (ArRobot.cpp): when true, the battery readings of the
     * Environment's states are ignored, so that {@link #setBatteryInfo} (an external battery's
     * readings) alone sets the voltages and state of charge.
     *
     * @param ignore whether to ignore the state's battery readings
     */
    public void setIgnoreMicroControllerBatteryInfo(boolean ignore) {
        underLock(() -> battery.setIgnoreReadings(ignore));
    }

    /**
     * Gives a battery reading, as ARIA's {@code ArRobot::setBatteryInfo} (ArRobot.cpp) does for an
     * external battery: both voltages join their averages; the state of charge is set if given.
     *
     * @param realBatteryVoltage       volts
     * @param normalizedBatteryVoltage volts on the 12 V scale
     * @param haveStateOfCharge        whether {@code stateOfCharge} is given
     * @param stateOfCharge            percent
     */
    public void setBatteryInfo(double realBatteryVoltage, double normalizedBatteryVoltage, boolean haveStateOfCharge,
                               double stateOfCharge) {
        long now = simulatedMs();
        underLock(() -> battery.setInfo(realBatteryVoltage, normalizedBatteryVoltage, haveStateOfCharge,
                stateOfCharge, now));
    }

    /** @return false: no temperature is simulated (ARIA's answer for a robot that reports −128) */
    public boolean hasTemperature() {
        return getTemperature() != -128;
    }

    /** @return −128, ARIA's value for no temperature reading */
    public int getTemperature() {
        return -128;
    }

    // ---- the motors ----

    /**
     * Enables the motors, as ARIA's {@code enableMotors} sends ENABLE 1 (ArRobot.cpp). A Pioneer's
     * motors are disabled when its program connects (unless the world says {@code motors="enabled"}):
     * until this call the velocity, move and heading commands are ignored, and the robot is told
     * once in its state's errors. {@link #areMotorsEnabled()} says so from the next cycle on.
     */
    public void enableMotors() {
        request(new Command.SetMotors(true));
    }

    /**
     * Disables the motors, as ARIA's {@code disableMotors} sends ENABLE 0: the robot stops at once
     * and ignores motion commands until {@link #enableMotors()}.
     */
    public void disableMotors() {
        request(new Command.SetMotors(false));
    }

    /**
     * Whether the motors are enabled, as the latest state says: like ARIA's, which reads the flag of
     * the latest SIP (ArRobot.h), it reflects {@link #enableMotors()} only after the next cycle.
     *
     * @return whether the robot reported its motors enabled; false before it has said
     */
    public boolean areMotorsEnabled() {
        RobotState s = state();
        return s != null && Boolean.TRUE.equals(s.motorsEnabled());
    }

    // ---- the wheel encoders ----

    /**
     * Asks for encoder packets, as ARIA's {@code ArRobot::requestEncoderPackets} (ArRobot.cpp): from the next cycle on,
     * {@link #getLeftEncoder()} and {@link #getRightEncoder()} count each wheel's travel in ticks of
     * the parameter file's {@code DistConvFactor}.
     */
    public void requestEncoderPackets() {
        encoders().setRequested(true);
    }

    /** Stops the encoder packets: the counts keep their values. */
    public void stopEncoderPackets() {
        encoders().setRequested(false);
    }

    /** @return whether encoder packets are requested */
    public boolean haveRequestedEncoderPackets() {
        return encoders().requested();
    }

    /** @return the left wheel's encoder count, ticks (0 until encoder packets are requested) */
    public long getLeftEncoder() {
        return encoders().left();
    }

    /** @return the right wheel's encoder count, ticks (0 until encoder packets are requested) */
    public long getRightEncoder() {
        return encoders().right();
    }

    private WheelEncoders encoders() {
        return wheelEncoders;
    }

    // ---- sonar ----

    /**
     * @return the simulated ms between firings of the sonar ring, from the parameter file's
     *         {@code SonarCycle} (what ARIA reads from a Pioneer's config packet): each firing reads
     *         one transducer of each bank of eight, in index order, and only those are new in that
     *         cycle ({@link #isSonarNew}); 0 when every transducer fires every step
     */
    public int getSonarCycle() {
        return sonarCycleMs;
    }

    /** @return the number of sonar units in the parameter file */
    public int getNumSonar() {
        return sonar.size();
    }

    /**
     * @param num the sonar's index
     * @return its range from the transducer in mm; 5000 (the maximum) if it never reported; −1 for a
     *         bad index
     */
    public int getSonarRange(int num) {
        return sonar.range(num);
    }

    /**
     * @param num the sonar's index
     * @return its reading, or null for a bad index
     */
    public ArSensorReading getSonarReading(int num) {
        return sonar.reading(num);
    }

    /**
     * @param num the sonar's index
     * @return whether its reading arrived in this cycle (ARIA: its counter equals the robot's);
     *         false for a bad index
     */
    public boolean isSonarNew(int num) {
        return sonar.isNew(num, counter);
    }

    /** Turns the sonars on (they are on after connecting). */
    public void enableSonar() {
        sonarEnabled = true;
        autonomousDrivingSonar = false;
        request(new Command.SetSonar(true));
    }

    /** Turns the sonars off: no new readings arrive until {@link #enableSonar()}. */
    public void disableSonar() {
        sonarEnabled = false;
        autonomousDrivingSonar = false;
        request(new Command.SetSonar(false));
    }

    /** @return whether the sonars are on */
    public boolean areSonarsEnabled() {
        return sonarEnabled;
    }

    /**
     * The nearest sonar range among the sonars mounted strictly inside an angle interval, by ARIA's
     * rule (see {@link ArMath#angleBetween}).
     *
     * @param startAngle degrees, robot-relative
     * @param endAngle   degrees, robot-relative
     * @return the range in mm, or −1 if no sonar is in the interval
     */
    public int getClosestSonarRange(double startAngle, double endAngle) {
        int n = getClosestSonarNumber(startAngle, endAngle);
        return n < 0 ? -1 : getSonarRange(n);
    }

    /**
     * @param startAngle degrees, robot-relative
     * @param endAngle   degrees, robot-relative
     * @return the index of the sonar with the nearest range inside the interval (ties to the lowest
     *         index), or −1 if none
     */
    public int getClosestSonarNumber(double startAngle, double endAngle) {
        return sonar.closest(startAngle, endAngle);
    }

    /**
     * Turns the sonars on as ARIA's {@code ArRobot::enableAutonomousDrivingSonar} (ArRobot.cpp) does: ARIA
     * then fires the sonar boards only while the robot drives; RoboSim's Pioneer has no such boards, so
     * the whole ring fires. {@link #areSonarsEnabled()} is false and {@link
     * #areAutonomousDrivingSonarsEnabled()} true, as in ARIA.
     */
    public void enableAutonomousDrivingSonar() {
        sonarEnabled = false;
        autonomousDrivingSonar = true;
        request(new Command.SetSonar(true));
    }

    /**
     * @return whether {@link #enableAutonomousDrivingSonar()} turned the sonars on (and they were not
     *     turned off since)
     */
    public boolean areAutonomousDrivingSonarsEnabled() {
        return autonomousDrivingSonar;
    }

    /**
     * Adds a sonar board as ARIA's {@code ArRobot::addSonar} (ArRobot.cpp): a range device kept by number
     * (ARIA's MTX sonar boards; a RoboSim program may list its {@link ArSonarDevice} here).
     *
     * @param sonar       the board
     * @param sonarNumber its number
     * @return false, with a log line, for null or a number another board has; true if added or already there
     */
    public boolean addSonar(ArRangeDevice sonar, int sonarNumber) {
        if (sonar == null) {
            LOG.info(() -> "robot " + getName()
                    + ": ArRobot::addSonar: Tried to add NULL sonar board as sonar number " + sonarNumber);
            return false;
        }
        synchronized (sonarBoards) {
            ArRangeDevice there = sonarBoards.get(sonarNumber);
            if (there == sonar) {
                return true;
            }
            if (there != null) {
                LOG.info(() -> "robot " + getName() + ": ArRobot::addSonar: Tried to add sonar board " + sonar.getName()
                        + " as sonar number " + sonarNumber + " but there is already a sonar of that number (called "
                        + there.getName() + ")");
                return false;
            }
            sonarBoards.put(sonarNumber, sonar);
            return true;
        }
    }

    /** @param sonar a board to remove @return false, with a log line, if it is null or not there */
    public boolean remSonar(ArRangeDevice sonar) {
        if (sonar == null) {
            LOG.info(() -> "robot " + getName() + ": ArRobot::remSonar: Passed NULL sonar board to remove");
            return false;
        }
        boolean removed = sonarBoards.values().remove(sonar);
        if (!removed) {
            LOG.info(() -> "robot " + getName() + ": ArRobot::remSonar: Could not find sonar board "
                    + sonar.getName() + " to remove");
        }
        return removed;
    }

    /** @param sonarNumber a board's number @return false, with a log line, if none has it */
    public boolean remSonar(int sonarNumber) {
        if (sonarBoards.remove(sonarNumber) == null) {
            LOG.info(() -> "robot " + getName() + ": ArRobot::remSonar: Could not find sonar board "
                    + sonarNumber + " to remove");
            return false;
        }
        return true;
    }

    /** @param sonarNumber a board's number @return the board, or null */
    public ArRangeDevice findSonar(int sonarNumber) {
        return sonarBoards.get(sonarNumber);
    }

    /** @param device a board @return whether it was added with {@link #addSonar} */
    public boolean hasSonar(ArRangeDevice device) {
        return sonarBoards.containsValue(device);
    }
}
