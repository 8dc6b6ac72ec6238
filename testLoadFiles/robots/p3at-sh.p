; Pioneer 3 AT with an SH microcontroller (firmware counts in mm): RoboSim robot model, ARIA's .p form (see docs/PARAMETER-FILES.md)
ConfigVersion 2.0

Section General settings
Class Pioneer
Subclass p3at-sh
RobotRadius 500        ; mm, the circle round the body
RobotDiagonal 120      ; mm
RobotWidth 505         ; mm
RobotLength 626        ; mm, bumper to bumper
RobotLengthFront 313   ; mm ahead of the turning centre
RobotLengthRear 313    ; mm behind it
MaxVelocity 1200       ; mm/s, the fastest the robot ever drives
MaxRVelocity 300       ; deg/s, the fastest it ever turns
FrontBumpers          true     ; a front bump ring (RoboSim's bodies have one)
NumFrontBumpers       5        ; number of front bumpers
RearBumpers           true     ; a rear bump ring (RoboSim's bodies have one)
NumRearBumpers        5        ; number of rear bumpers

Section Conversion factors
; firmware units to ARIA's: what a Pioneer protocol server speaks
AngleConvFactor 0.001534 ; rad per angle unit (2 pi / 4096)
DistConvFactor 1.0     ; mm per distance unit
VelConvFactor 1.0      ; mm/s per speed unit
RangeConvFactor 1.0    ; mm per sonar range unit
DiffConvFactor 0.0034  ; rad/s per mm/s of wheel speed difference
Vel2Divisor 20         ; VEL2 wheel speed divisor

Section Movement control parameters
; 0: the firmware's own value (RoboSim: 300 mm/s2 and 100 deg/s2)
TransAccel 0
TransDecel 0
RotAccel 0
RotDecel 0

Section Sonar parameters
SonarNum 16            ; transducers
SonarCycle 40                 ; ms between firings, one transducer of each bank of 8 (RoboSim key)
; SonarUnit <number> <x mm forward> <y mm left> <heading deg>
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
LaserX 125             ; mm forward of the centre
LaserY 0               ; on the centre line
LaserTh 0              ; facing forward
LaserMaxRange 0        ; 0: the laser's default (8000 mm)
