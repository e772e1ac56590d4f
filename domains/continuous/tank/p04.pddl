; Three tanks, six fields, two pumps (pump1 fills tank1 or tank2, pump2
; tank2 or tank3). field2 needs 70 from tank1 (capacity 50), field3 90
; from tank2 (capacity 60): both must be irrigated while their tank is
; filled. field6 (60) draws on tank2 or tank3; tank3 (capacity 40) starts
; full but field5 drains it too.
(define (problem tank-p04) (:domain tank)
  (:objects
    tank1 tank2 tank3 - tank
    pump1 pump2 - pump
    field1 field2 field3 field4 field5 field6 - field)
  (:init
    (pipe pump1 tank1) (pipe pump1 tank2) (pump-idle pump1) (= (pump-rate pump1) 6) (= (pump-shift pump1) 30)
    (pipe pump2 tank2) (pipe pump2 tank3) (pump-idle pump2) (= (pump-rate pump2) 5) (= (pump-shift pump2) 30)
    (= (level tank1) 35) (= (capacity tank1) 50)
    (= (level tank2) 0) (= (capacity tank2) 60)
    (= (level tank3) 40) (= (capacity tank3) 40)
    (feeds tank1 field1) (dry field1) (= (flow-rate field1) 5) (= (irrigation-time field1) 6)
    (feeds tank1 field2) (dry field2) (= (flow-rate field2) 7) (= (irrigation-time field2) 10)
    (feeds tank2 field3) (dry field3) (= (flow-rate field3) 9) (= (irrigation-time field3) 10)
    (feeds tank2 field4) (dry field4) (= (flow-rate field4) 4) (= (irrigation-time field4) 10)
    (feeds tank3 field5) (dry field5) (= (flow-rate field5) 3) (= (irrigation-time field5) 10)
    (feeds tank2 field6) (feeds tank3 field6) (dry field6) (= (flow-rate field6) 6) (= (irrigation-time field6) 10))
  (:goal (and (watered field1) (watered field2) (watered field3) (watered field4) (watered field5) (watered field6)))
  (:metric minimize (total-time)))
