; PeopleBot (SH microcontroller: firmware counts in mm): RoboSim robot model, ARIA's .p form (see docs/PARAMETER-FILES.md)
ConfigVersion 2.0

Section General settings
Class Pioneer
Subclass peoplebot-sh
RobotRadius 340        ; mm, the circle round the body
RobotDiagonal 120      ; mm
RobotWidth 425         ; mm
RobotLength 513        ; mm, bumper to bumper
; no RobotLengthFront/Rear: the length is split evenly about the centre
MaxVelocity 2200       ; mm/s, the fastest the robot ever drives
MaxRVelocity 500       ; deg/s, the fastest it ever turns

Section Conversion factors
; firmware units to ARIA's: what a Pioneer protocol server speaks
AngleConvFactor 0.001534 ; rad per angle unit (2 pi / 4096)
DistConvFactor 1.0     ; mm per distance unit
VelConvFactor 1.0      ; mm/s per speed unit
RangeConvFactor 1.0    ; mm per sonar range unit
DiffConvFactor 0.006   ; rad/s per mm/s of wheel speed difference
Vel2Divisor 20         ; VEL2 wheel speed divisor

Section Movement control parameters
; 0: the firmware's own value (RoboSim: 300 mm/s2 and 100 deg/s2)
TransAccel 0
TransDecel 0
RotAccel 0
RotDecel 0

Section Sonar parameters
SonarNum 32            ; transducers; two rings: the base ring (0-15) and the upper ring (16-31)
; SonarUnit <number> <x mm forward> <y mm left> <heading deg>
SonarUnit 0 69 136 90
SonarUnit 1 114 119 50
SonarUnit 2 148 78 30
SonarUnit 3 166 27 10
SonarUnit 4 166 -27 -10
SonarUnit 5 148 -78 -30
SonarUnit 6 114 -119 -50
SonarUnit 7 69 -136 -90
SonarUnit 8 -157 -136 -90
SonarUnit 9 -203 -119 -130
SonarUnit 10 -237 -78 -150
SonarUnit 11 -255 -27 -170
SonarUnit 12 -255 27 170
SonarUnit 13 -237 78 150
SonarUnit 14 -203 119 130
SonarUnit 15 -157 136 90
SonarUnit 16 -20 136 90
SonarUnit 17 24 119 50
SonarUnit 18 58 78 30
SonarUnit 19 77 27 10
SonarUnit 20 77 -27 -10
SonarUnit 21 58 -78 -30
SonarUnit 22 24 -119 -50
SonarUnit 23 -20 -136 -90
SonarUnit 24 -191 -136 -90
SonarUnit 25 -237 -119 -130
SonarUnit 26 -271 -78 -150
SonarUnit 27 -290 -27 -170
SonarUnit 28 -290 27 170
SonarUnit 29 -271 78 150
SonarUnit 30 -237 119 130
SonarUnit 31 -191 136 90

Section Laser parameters
LaserX 21              ; mm forward of the centre
LaserY 0               ; on the centre line
LaserTh 0              ; facing forward
LaserMaxRange 0        ; 0: the laser's default (8000 mm)
