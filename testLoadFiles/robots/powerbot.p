; PowerBot: RoboSim robot model, ARIA's .p form (see docs/PARAMETER-FILES.md)
ConfigVersion 2.0

Section General settings
Class Pioneer
Subclass powerbot
RobotRadius 550        ; mm, the circle round the body
RobotDiagonal 240      ; mm
RobotWidth 680         ; mm
RobotLength 911        ; mm, bumper to bumper
RobotLengthFront 369   ; mm ahead of the turning centre
RobotLengthRear 542    ; mm behind it
MaxVelocity 2000       ; mm/s, the fastest the robot ever drives
MaxRVelocity 360       ; deg/s, the fastest it ever turns

Section Conversion factors
; firmware units to ARIA's: what a Pioneer protocol server speaks
AngleConvFactor 0.001534 ; rad per angle unit (2 pi / 4096)
DistConvFactor 0.5813  ; mm per distance unit
VelConvFactor 1.0      ; mm/s per speed unit
RangeConvFactor 1.0    ; mm per sonar range unit
DiffConvFactor 0.00373 ; rad/s per mm/s of wheel speed difference
Vel2Divisor 20         ; VEL2 wheel speed divisor

Section Movement control parameters
; 0: the firmware's own value (RoboSim: 300 mm/s2 and 100 deg/s2)
TransAccel 0
TransDecel 0
RotAccel 0
RotDecel 0

Section Sonar parameters
SonarNum 31            ; transducers; units 7, 15 and 23 are unfitted: at the centre, facing back
; SonarUnit <number> <x mm forward> <y mm left> <heading deg>
SonarUnit 0 152 278 90
SonarUnit 1 200 267 65
SonarUnit 2 241 238 45
SonarUnit 3 274 200 35
SonarUnit 4 300 153 25
SonarUnit 5 320 96 15
SonarUnit 6 332 33 5
SonarUnit 7 0 0 -180
SonarUnit 8 332 -33 -5
SonarUnit 9 320 -96 -15
SonarUnit 10 300 -153 -25
SonarUnit 11 274 -200 -35
SonarUnit 12 241 -238 -45
SonarUnit 13 200 -267 -65
SonarUnit 14 152 -278 -90
SonarUnit 15 0 0 -180
SonarUnit 16 -298 -278 -90
SonarUnit 17 -347 -267 -115
SonarUnit 18 -388 -238 -135
SonarUnit 19 -420 -200 -145
SonarUnit 20 -447 -153 -155
SonarUnit 21 -467 -96 -165
SonarUnit 22 -478 -33 -175
SonarUnit 23 0 0 -180
SonarUnit 24 -478 33 175
SonarUnit 25 -467 96 165
SonarUnit 26 -447 153 155
SonarUnit 27 -420 200 145
SonarUnit 28 -388 238 135
SonarUnit 29 -347 267 115
SonarUnit 30 -298 278 90

Section Laser parameters
LaserX 251             ; mm forward of the centre
LaserY 0               ; on the centre line
LaserTh 0              ; facing forward
LaserMaxRange 0        ; 0: the laser's default (8000 mm)
