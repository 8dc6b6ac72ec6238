ConfigVersion 2.0
;SectionFlags for : 
Section General settings
;  Robot parameters for the Pioneer 3 AT (p3at), ARIA's .p form
Class Pioneer                 ; general type of robot
Subclass p3at                 ; specific type of robot
RobotRadius           500      ; radius in mm
RobotDiagonal         120      ; half-height to diagonal of octagon
RobotWidth            505      ; width in mm
RobotLength           626      ; length in mm of the whole robot
RobotLengthFront      313      ; length in mm to the front of the robot
RobotLengthRear       313      ; length in mm to the rear of the robot
MaxVelocity           1200     ; absolute maximum velocity, mm/s
MaxRVelocity          300      ; absolute maximum rotational velocity, deg/s
TransAccel            300      ; translational acceleration, mm/s/s
TransDecel            300      ; translational deceleration, mm/s/s
RotAccel              100      ; rotational acceleration, deg/s/s
RotDecel              100      ; rotational deceleration, deg/s/s
DiffConvFactor        0.0034   ; wheel speed difference to rad/s
FrontBumpers          true     ; a front bump ring (RoboSim's bodies have one)
NumFrontBumpers       5        ; number of front bumpers
RearBumpers           true     ; a rear bump ring (RoboSim's bodies have one)
NumRearBumpers        5        ; number of rear bumpers

Section Conversion factors
; firmware units to ARIA's: what a Pioneer protocol server speaks
AngleConvFactor       0.001534 ; rad per angle unit (2 pi / 4096)
DistConvFactor        0.465    ; mm per distance unit
VelConvFactor         1.0      ; mm/s per speed unit
RangeConvFactor       1.0      ; mm per sonar range unit
Vel2Divisor           20       ; VEL2 wheel speed divisor

Section Sonar parameters
SonarNum 16                   ; number of sonar
SonarCycle 40                 ; ms between firings, one transducer of each bank of 8 (RoboSim key)
;SonarUnit <Number> <x position, mm> <y position, mm> <heading of disc, degrees>
SonarUnit 0 147 136 90
SonarUnit 1 193 119 50
SonarUnit 2 227 79 30
SonarUnit 3 245 27 10
SonarUnit 4 245 -27 -10
SonarUnit 5 227 -79 -30
SonarUnit 6 193 -119 -50
SonarUnit 7 147 -136 -90
SonarUnit 8 -144 -136 -90
SonarUnit 9 -189 -119 -130
SonarUnit 10 -223 -79 -150
SonarUnit 11 -241 -27 -170
SonarUnit 12 -241 27 170
SonarUnit 13 -223 79 150
SonarUnit 14 -189 119 130
SonarUnit 15 -144 136 90

Section Laser parameters
LaserX 160                    ; x location of laser, mm
LaserY 0                      ; y location of laser, mm
LaserTh 0                     ; rotation of laser, deg
LaserMaxRange 8000            ; max range of laser, mm (0: the default, 8000)
