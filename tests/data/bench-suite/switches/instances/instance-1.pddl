(define (problem both) (:domain switches) (:init) (:goal (and (on-a) (on-b))))
